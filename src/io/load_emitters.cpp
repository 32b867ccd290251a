// Builders for free-standing <emitter>s (area emitters live inside shapes).
#include <functional>

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

using EmitterFactory = std::function<std::unique_ptr<Light>(const Properties&)>;

const std::map<std::string, EmitterFactory>& EmitterRegistry() {
  static const std::map<std::string, EmitterFactory> registry = {
      {"point",
       [](const Properties& p) -> std::unique_ptr<Light> {
         Vec3f pos = p.Has("position") ? Vec3f(p.Point("position", Vec3d(0.0)))
                                       : p.GetTransform("to_world").Point(Vec3f(0.f));
         CheckWithinSceneLimit(pos, p.Has("position") ? p.LocOf("position") : p.LocOf("to_world"), "the point light");
         return std::make_unique<PointLight>(pos, Illuminant(p, "intensity", 1));
       }},
      {"spot",
       [](const Properties& p) -> std::unique_ptr<Light> {
         Transform t = p.GetTransform("to_world");
         float cutoff = float(p.FloatIn("cutoff_angle", 20, 1e-3, 90));
         float beam = float(p.FloatIn("beam_width", cutoff * 0.75, 0, 90));
         CheckWithinSceneLimit(t.Point(Vec3f(0.f)), p.LocOf("to_world"), "the spot light");
         return std::make_unique<SpotLight>(t.Point(Vec3f(0.f)), UnitVector(t.Vector(Vec3f(0, 0, 1)), p.LocOf("to_world"), "the direction"),
                                            Illuminant(p, "intensity", 1), cutoff, beam);
       }},
      {"directional",
       [](const Properties& p) -> std::unique_ptr<Light> {
         Vec3f dir = p.Has("direction") ? Vec3f(p.Vector("direction", Vec3d(0, 0, 1)))
                                        : p.GetTransform("to_world").Vector(Vec3f(0, 0, 1));
         dir = UnitVector(dir, p.Has("direction") ? p.LocOf("direction") : p.LocOf("to_world"), "direction");
         return std::make_unique<DirectionalLight>(dir, Illuminant(p, "irradiance", 1));
       }},
      {"constant",
       [](const Properties& p) -> std::unique_ptr<Light> {
         return std::make_unique<ConstantEnvironment>(Illuminant(p, "radiance", 1));
       }},
      {"envmap",
       [](const Properties& p) -> std::unique_ptr<Light> {
         std::string file = ResolvePath(p.LocOf("filename"), p.String("filename"));
         float scale = float(p.FloatIn("scale", 1, 0, 1e30));
         Image img = ReadImageRgb(file, false);
         return std::make_unique<EnvironmentMap>(std::move(img), scale, p.GetTransform("to_world"));
       }},
  };
  return registry;
}

}  // namespace

std::unique_ptr<Light> BuildEmitter(const ObjectNode& node, LoaderContext&) {
  if (node.type == "area") throw ErrorAt(node.loc, "an area emitter must be nested inside a <shape>");
  const auto& registry = EmitterRegistry();
  auto it = registry.find(node.type);
  if (it == registry.end()) UnknownType(node, registry);
  Properties props(node);
  auto light = it->second(props);
  props.WarnUnused();
  return light;
}

}  // namespace objektiv
