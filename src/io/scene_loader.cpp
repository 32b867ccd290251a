#include "io/scene_loader.h"

#include <filesystem>

#include "base/log.h"
#include "base/text_file.h"
#include "io/loader_context.h"

namespace objektiv {

std::string ResolvePath(const Location& loc, const std::string& filename) {
  namespace fs = std::filesystem;
  fs::path p(filename);
  if (p.is_relative()) p = fs::path(loc.file).parent_path() / p;
  if (!fs::exists(p)) throw ErrorAt(loc, "file not found: '{}'", p.string());
  // Its reader checks it again, with the size limit for its kind.
  try {
    CheckInputFile(p.string(), "file", UINTMAX_MAX);
  } catch (const InputError& e) {
    throw ErrorAt(loc, "{}", e.what());
  }
  return p.string();
}

void CheckWithinSceneLimit(const Vec3f& p, const Location& loc, const char* what) {
  if (!WithinSceneLimit(p))
    throw ErrorAt(loc, "{} at ({:g}, {:g}, {:g}) lies beyond the scene's coordinate limit of {:g}", what, p.x, p.y, p.z,
                  kMaxSceneCoordinate);
}

Vec3f UnitVector(const Vec3f& v, const Location& loc, const char* what) {
  float m = MaxComponent(Abs(v));
  if (!(m > 0) || !std::isfinite(m)) throw ErrorAt(loc, "{} must be finite and not zero", what);
  return Normalize(v / m);
}

const ObjectNode* OneChild(const Properties& p, const std::string& tag) {
  auto c = p.Children(tag);
  if (c.size() > 1) throw ErrorAt(c[1]->loc, "only one <{}> is allowed here", tag);
  return c.empty() ? nullptr : c[0].get();
}

std::unique_ptr<Sampler> MakeSampler(const SamplerSettings& s) {
  return std::make_unique<Sampler>(s.kind, s.spp, s.seed, s.pattern, s.adaptive);
}

std::vector<PluginKind> ScenePluginKinds() {
  return {IntegratorPlugins().Describe(), SensorPlugins().Describe(),  FilmPlugins().Describe(),
          FilterPlugins().Describe(),     SamplerPlugins().Describe(), ShapePlugins().Describe(),
          MaterialPlugins().Describe(),   TexturePlugins().Describe(), EmitterPlugins().Describe()};
}

namespace {

RenderSetup Build(const SceneDocument& doc, const GlassCatalog& glasses) {
  RenderSetup setup;
  setup.scene = std::make_unique<Scene>();
  LoaderContext ctx{*setup.scene, glasses};
  const ObjectNode& root = *doc.root;
  const ObjectNode* sensor = nullptr;
  const ObjectNode* integrator = nullptr;
  for (const auto& child : root.children) {
    if (child->tag == "shape") {
      BuildShape(*child, ctx);
    } else if (child->tag == "emitter") {
      setup.scene->AddLight(BuildEmitter(*child, ctx));
    } else if (child->tag == "sensor") {
      if (sensor) throw ErrorAt(child->loc, "only one <sensor> is supported (first at line {})", sensor->loc.line);
      sensor = child.get();
    } else if (child->tag == "integrator") {
      if (integrator) throw ErrorAt(child->loc, "only one <integrator> is allowed");
      integrator = child.get();
    } else if (child->tag == "bsdf") {
      // Declared for later <ref>s; built (and checked) now.
      BuildMaterial(*child, ctx);
    } else if (child->tag == "texture") {
      BuildTexture(*child, SpectrumUsage::kAlbedo, ctx);
    } else {
      throw ErrorAt(child->loc, "<{}> cannot appear directly in <scene>", child->tag);
    }
  }
  for (const Property& p : root.props)
    throw ErrorAt(p.loc, "property '{}' cannot appear directly in <scene>", p.name);
  if (!sensor) throw ErrorAt(root.loc, "the scene has no <sensor>");
  BuildSensor(*sensor, glasses, setup);
  setup.scene->Commit();
  setup.integrator = BuildIntegrator(integrator, *setup.scene);
  if (setup.integrator->TracesLightToCamera() && !setup.camera->HasImportance())
    throw ErrorAt(integrator->loc,
                  "this integrator carries light paths to the camera (ptracer, or path with caustics), and light "
                  "cannot find this '{}' sensor: perspective, thinlens and realistic (its exact lens, not lens_model "
                  "thick or thin) can be found, and a stereo rig of them",
                  sensor->type);
  if (setup.scene->lights().empty() && !setup.integrator->LightsTheSceneItself()) spdlog::warn("{}: the scene has no emitters; the image will be black", root.loc.file);
  return setup;
}

}  // namespace

RenderSetup LoadScene(const std::string& path, const std::map<std::string, std::string>& defines,
                      const GlassCatalog& glasses) {
  return Build(ParseSceneFile(path, defines), glasses);
}

RenderSetup LoadSceneFromString(const std::string& xml, const std::string& name,
                                const std::map<std::string, std::string>& defines, const GlassCatalog& glasses) {
  return Build(ParseSceneString(xml, name, defines), glasses);
}

}  // namespace objektiv
