#include "io/scene_loader.h"

#include <filesystem>

#include "base/log.h"
#include "base/text_file.h"
#include "camera/realistic_camera.h"
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
          MaterialPlugins().Describe(),   TexturePlugins().Describe(), EmitterPlugins().Describe(),
          MediumPlugins().Describe(),     PhasePlugins().Describe()};
}

namespace {

// Media (and null medium boundaries) are followed by the path tracer only: the other
// integrators, the path tracer's light paths (caustics) and the realistic camera's light-traced
// lens effects would render such a scene without them, so they refuse it.
void CheckMediaSupport(const RenderSetup& setup, const ObjectNode* integrator, const ObjectNode* sensor,
                       const ObjectNode& root) {
  if (!setup.scene->HasMedia()) return;
  const Location& at = integrator ? integrator->loc : root.loc;
  const std::string type = integrator ? integrator->type : "path";
  if (!setup.integrator->RendersMedia())
    throw ErrorAt(at, "the scene has participating media or null BSDFs, which the '{}' integrator{} does not render "
                  "(only 'path' follows light through media, and not with caustics)", type,
                  setup.integrator->TracesLightToCamera() && type == "path" ? " with caustics" : "");
  if (type == "aov")
    spdlog::warn("{}:{}: aov: the image follows the media, but the AOVs describe the first surface a camera ray "
                 "hits (a null medium boundary included) and see no medium", at.file, at.line);
  const auto* real = dynamic_cast<const RealisticCamera*>(setup.camera.get());
  if (real && real->effects().Any())
    throw ErrorAt(sensor->loc, "the lens's ghosts and diffraction (realistic sensor) trace light without the scene's "
                  "participating media and null BSDFs: turn them off in a scene with media");
}

// SPPM shares each iteration's four wavelengths between all its camera paths and photons; a
// camera ray through dispersive glass keeps one of them, the same one across the whole image,
// and the iterations' unequal weights in the progressive estimate leave a colour cast (grey
// came out (-0.30, 1.00, 0.67) after 32 iterations): refused rather than rendered wrong.
void CheckSppmCamera(const RenderSetup& setup, const ObjectNode* integrator) {
  if (!integrator || integrator->type != "sppm") return;
  const auto* real = dynamic_cast<const RealisticCamera*>(setup.camera.get());
  if (real && real->dispersive())
    throw ErrorAt(integrator->loc, "sppm cannot render through a lens of dispersive glasses ({}): each camera ray "
                  "keeps one wavelength, which sppm shares over the whole image in an iteration; use 'path' or "
                  "'ptracer', or a lens of constant indices", real->lens().prescription().name);
}

}  // namespace

RenderSetup BuildScene(const SceneDocument& doc, const GlassCatalog& glasses) {
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
    } else if (child->tag == "medium") {
      // Declared for the <ref>s of shapes and the sensor; built (and checked) now.
      BuildMedium(*child, ctx);
    } else {
      throw ErrorAt(child->loc, "<{}> cannot appear directly in <scene>", child->tag);
    }
  }
  for (const Property& p : root.props)
    throw ErrorAt(p.loc, "property '{}' cannot appear directly in <scene>", p.name);
  if (!sensor) throw ErrorAt(root.loc, "the scene has no <sensor>");
  BuildSensor(*sensor, ctx, setup);
  for (const auto& child : root.children)
    if (child->tag == "medium" && !ctx.attached_media.count(child.get()))
      throw ErrorAt(child->loc, "this <medium> fills nothing: attach it to a shape (<ref name=\"interior\" id=\"...\"/> "
                    "or name=\"exterior\") or to the <sensor> (<ref id=\"...\"/>)");
  setup.scene->Commit();
  setup.integrator = BuildIntegrator(integrator, *setup.scene);
  CheckMediaSupport(setup, integrator, sensor, root);
  CheckSppmCamera(setup, integrator);
  if (setup.integrator->TracesLightToCamera() && !setup.camera->HasImportance())
    throw ErrorAt(integrator->loc,
                  "this integrator carries light paths to the camera (ptracer, or path with caustics), and light "
                  "cannot find this '{}' sensor: perspective, thinlens and realistic (its exact lens, not lens_model "
                  "thick or thin) can be found, and a stereo rig of them",
                  sensor->type);
  if (setup.scene->lights().empty() && !setup.integrator->LightsTheSceneItself()) spdlog::warn("{}: the scene has no emitters; the image will be black", root.loc.file);
  return setup;
}

RenderSetup LoadScene(const std::string& path, const std::map<std::string, std::string>& defines,
                      const GlassCatalog& glasses) {
  return BuildScene(ParseSceneFile(path, defines), glasses);
}

RenderSetup LoadSceneFromString(const std::string& xml, const std::string& name,
                                const std::map<std::string, std::string>& defines, const GlassCatalog& glasses) {
  return BuildScene(ParseSceneString(xml, name, defines), glasses);
}

}  // namespace objektiv
