// The <emitter> plugins: lights of their own, and the area emitter (nested in a shape).
#include "io/image_io.h"
#include "io/loader_context.h"
#include "scene/infinite_light.h"

namespace objektiv {
namespace {

Spectrum Illuminant(const Properties& p, const std::string& name, float fallback) {
  if (auto v = p.SpectrumProp(name)) return MakeSpectrum(*v, SpectrumUsage::kIlluminant);
  SpectrumValue s;
  s.kind = SpectrumValue::Kind::kConstant;
  s.value = fallback;
  return MakeSpectrum(s, SpectrumUsage::kIlluminant);
}

using EmitterPlugin = EmitterRegistry::PluginType;

// A plugin making a light of its own from its properties.
EmitterPlugin LightPlugin(const char* type, std::vector<PropertyDecl> properties,
                          std::unique_ptr<Light> (*make)(const Properties&)) {
  return {type, std::move(properties), [make](const Properties& p, LoaderContext&) { return Emission{make(p)}; }};
}

std::unique_ptr<Light> MakePoint(const Properties& p) {
  Vec3f pos = p.Has("position") ? Vec3f(p.Point("position", Vec3d(0.0))) : p.GetTransform("to_world").Point(Vec3f(0.f));
  CheckWithinSceneLimit(pos, p.Has("position") ? p.LocOf("position") : p.LocOf("to_world"), "the point light");
  return std::make_unique<PointLight>(pos, Illuminant(p, "intensity", 1));
}

std::unique_ptr<Light> MakeSpot(const Properties& p) {
  Transform t = p.GetTransform("to_world");
  float cutoff = float(p.FloatIn("cutoff_angle", 20, 1e-3, 90));
  float beam = float(p.FloatIn("beam_width", cutoff * 0.75, 0, 90));
  CheckWithinSceneLimit(t.Point(Vec3f(0.f)), p.LocOf("to_world"), "the spot light");
  return std::make_unique<SpotLight>(t.Point(Vec3f(0.f)),
                                     UnitVector(t.Vector(Vec3f(0, 0, 1)), p.LocOf("to_world"), "the direction"),
                                     Illuminant(p, "intensity", 1), cutoff, beam);
}

std::unique_ptr<Light> MakeDirectional(const Properties& p) {
  Vec3f dir = p.Has("direction") ? Vec3f(p.Vector("direction", Vec3d(0, 0, 1)))
                                 : p.GetTransform("to_world").Vector(Vec3f(0, 0, 1));
  dir = UnitVector(dir, p.Has("direction") ? p.LocOf("direction") : p.LocOf("to_world"), "direction");
  return std::make_unique<DirectionalLight>(dir, Illuminant(p, "irradiance", 1));
}

std::unique_ptr<Light> MakeEnvmap(const Properties& p) {
  std::string file = ResolvePath(p.LocOf("filename"), p.String("filename"));
  float scale = float(p.FloatIn("scale", 1, 0, 1e30));
  Image img = ReadImageRgb(file, false);
  return std::make_unique<EnvironmentMap>(std::move(img), scale, p.GetTransform("to_world"));
}

// The emission of the shape the area emitter is nested in (see AddSurfaces).
Emission MakeArea(const Properties& p, LoaderContext& ctx) {
  Emission e;
  e.area_radiance = GetTexture(p, "radiance", SpectrumUsage::kIlluminant, 1, ctx);
  e.two_sided = p.Bool("two_sided", false);
  return e;
}

}  // namespace

const EmitterRegistry& EmitterPlugins() {
  static const EmitterRegistry registry(
      "emitter", {},
      {
          {"area", {{"radiance", PropType::kSpectrumOrTexture}, {"two_sided", PropType::kBoolean}}, MakeArea},
          LightPlugin(
              "point",
              {{"position", PropType::kPoint}, {"to_world", PropType::kTransform}, {"intensity", PropType::kSpectrum}},
              MakePoint),
          LightPlugin("spot",
                      {{"to_world", PropType::kTransform},
                       {"intensity", PropType::kSpectrum},
                       {"cutoff_angle", PropType::kFloat},
                       {"beam_width", PropType::kFloat}},
                      MakeSpot),
          LightPlugin("directional",
                      {{"direction", PropType::kVector},
                       {"to_world", PropType::kTransform},
                       {"irradiance", PropType::kSpectrum}},
                      MakeDirectional),
          LightPlugin("constant", {{"radiance", PropType::kSpectrum}},
                      [](const Properties& p) -> std::unique_ptr<Light> {
                        return std::make_unique<ConstantEnvironment>(Illuminant(p, "radiance", 1));
                      }),
          LightPlugin(
              "envmap",
              {{"filename", PropType::kString}, {"scale", PropType::kFloat}, {"to_world", PropType::kTransform}},
              MakeEnvmap),
      });
  return registry;
}

std::unique_ptr<Light> BuildEmitter(const ObjectNode& node, LoaderContext& ctx) {
  if (node.type == "area") throw ErrorAt(node.loc, "an area emitter must be nested inside a <shape>");
  return EmitterPlugins().Build(node, ctx).light;
}

}  // namespace objektiv
