// Builders for <sensor> (with its <film>, <rfilter> and <sampler>) and <integrator>.
#include <cmath>
#include <functional>

#include "base/log.h"
#include "io/loader_context.h"

namespace objektiv {
namespace {

using FilterFactory = std::function<std::shared_ptr<const Filter>(const Properties&)>;

std::shared_ptr<const Filter> BuildFilter(const ObjectNode* node) {
  if (!node) return std::make_shared<GaussianFilter>(0.5f);  // Mitsuba's default
  static const std::map<std::string, FilterFactory> registry = {
      {"box", [](const Properties& p) { return std::make_shared<BoxFilter>(float(p.FloatIn("radius", 0.5, 1e-3, 16))); }},
      {"tent", [](const Properties& p) { return std::make_shared<TentFilter>(float(p.FloatIn("radius", 1.0, 1e-3, 16))); }},
      {"gaussian",
       [](const Properties& p) { return std::make_shared<GaussianFilter>(float(p.FloatIn("stddev", 0.5, 1e-3, 4))); }},
      {"blackman-harris",
       [](const Properties& p) { return std::make_shared<BlackmanHarrisFilter>(float(p.FloatIn("radius", 1.5, 1e-3, 16))); }},
  };
  auto it = registry.find(node->type);
  if (it == registry.end()) UnknownType(*node, registry);
  Properties p(*node);
  std::shared_ptr<const Filter> f = it->second(p);
  p.WarnUnused();
  return f;
}

const ObjectNode* OneChild(const Properties& p, const std::string& tag) {
  auto c = p.Children(tag);
  if (c.size() > 1) throw ErrorAt(c[1]->loc, "only one <{}> is allowed here", tag);
  return c.empty() ? nullptr : c[0].get();
}

FilmSettings BuildFilm(const ObjectNode* node) {
  FilmSettings f;
  if (!node) {
    f.filter = BuildFilter(nullptr);
    f.crop = {0, 0, f.width, f.height};
    return f;
  }
  if (node->type != "hdrfilm") throw ErrorAt(node->loc, "unknown film type '{}' (known: hdrfilm)", node->type);
  Properties p(*node);
  f.width = int(p.IntIn("width", 768, 1, 1 << 16));
  f.height = int(p.IntIn("height", 576, 1, 1 << 16));
  int cx = int(p.IntIn("crop_offset_x", 0, 0, f.width - 1)), cy = int(p.IntIn("crop_offset_y", 0, 0, f.height - 1));
  int cw = int(p.IntIn("crop_width", f.width - cx, 1, f.width - cx));
  int ch = int(p.IntIn("crop_height", f.height - cy, 1, f.height - cy));
  f.crop = {cx, cy, cx + cw, cy + ch};
  f.exposure = float(p.FloatIn("exposure", 0, -64, 64));
  std::string tm = p.Choice("tonemap", "clamp", {"clamp", "filmic"});
  f.tonemap = *ParseToneMap(tm);
  f.color_space = ColorSpace::ByName(p.Choice("color_space", "rec709", {"rec709", "acescg"}));
  // Mitsuba's output-format properties: the EXR is always RGB float32 (another choice is warned about).
  const std::string pixel = p.Choice("pixel_format", "rgb", {"rgb", "rgba"});
  const std::string component = p.Choice("component_format", "float32", {"float16", "float32"});
  p.Choice("file_format", "openexr", {"openexr", "exr"});
  if (pixel != "rgb" || component != "float32") {
    const Location& at = p.LocOf(pixel != "rgb" ? "pixel_format" : "component_format");
    spdlog::warn("{}:{}: film: the EXR is written as rgb float32, not {} {}", at.file, at.line, pixel, component);
  }
  f.filter = BuildFilter(OneChild(p, "rfilter"));
  p.WarnUnused();
  return f;
}

SamplerSettings BuildSamplerSettings(const ObjectNode* node) {
  SamplerSettings s;
  if (!node) return s;
  Properties p(*node);
  static const std::map<std::string, std::string> kinds = {
      {"independent", "independent"}, {"stratified", "stratified"}, {"multijitter", "stratified"},
      {"sobol", "sobol"},             {"ldsampler", "sobol"},       {"orthogonal", "stratified"}};
  auto it = kinds.find(node->type);
  if (it == kinds.end()) UnknownType(*node, kinds);
  s.type = it->second;
  s.spp = int(p.IntIn("sample_count", 4, 1, 1 << 24));
  s.seed = uint64_t(p.IntIn("seed", 0, 0, INT64_MAX));
  if (!p.Bool("jitter", true))  // stratified/multijitter: always jittered here
    spdlog::warn("{}:{}: sampler: jitter = false is not supported; samples are jittered", p.LocOf("jitter").file,
                 p.LocOf("jitter").line);
  p.WarnUnused();
  return s;
}

// Mitsuba's focal_length: "50mm" (or a number) on a 36 x 24 mm film, measured on the diagonal.
double FocalLengthMm(const Properties& p) {
  std::string s = p.Has("focal_length") ? std::string() : "";
  const Property* prop = nullptr;
  for (const Property& q : p.node().props)
    if (q.name == "focal_length") prop = &q;
  double f;
  if (std::holds_alternative<std::string>(prop->data)) {
    s = p.String("focal_length");
    if (s.size() > 2 && s.substr(s.size() - 2) == "mm") s = s.substr(0, s.size() - 2);
    char* end = nullptr;
    f = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || *end != '\0') throw ErrorAt(prop->loc, "focal_length '{}' is not a length like \"50mm\"", s);
  } else {
    f = p.Float("focal_length");
  }
  if (!(f > 0)) throw ErrorAt(prop->loc, "focal_length must be positive");
  return f;
}

// What every sensor type is built from besides its own properties.
struct SensorBase {
  Transform to_world;
  int width, height;
  float far_clip;
};

// The clip planes, read only by the sensors that use them (the realistic camera starts its
// rays at the lens's front, so near_clip would be ignored there: it is warned about).
float NearClip(const Properties& p, float far_clip) {
  float near_clip = float(p.FloatIn("near_clip", 1e-2, 0, 1e30));
  if (!(far_clip > near_clip)) throw ErrorAt(p.LocOf("far_clip"), "far_clip must exceed near_clip");
  return near_clip;
}

std::unique_ptr<Camera> BuildPerspective(const Properties& p, const SensorBase& b, bool thin) {
  static const std::map<std::string, FovAxis> axes = {{"x", FovAxis::kX},
                                                      {"y", FovAxis::kY},
                                                      {"diagonal", FovAxis::kDiagonal},
                                                      {"smaller", FovAxis::kSmaller},
                                                      {"larger", FovAxis::kLarger}};
  const float near_clip = NearClip(p, b.far_clip);
  const int w = b.width, h = b.height;
  float fov;
  FovAxis axis;
  // Sensor width in mm relates field of view and focal length (default: 36 mm full frame).
  double sensor_width = p.FloatIn("sensor_width", 36, 1e-3, 1e4);
  double focal_mm;
  if (p.Has("focal_length")) {
    if (p.Has("fov")) throw ErrorAt(p.LocOf("fov"), "give either fov or focal_length, not both");
    focal_mm = FocalLengthMm(p);
    if (p.Has("sensor_width")) {
      fov = float(2 * std::atan(sensor_width / (2 * focal_mm)) * 180 / M_PI);
      axis = FovAxis::kX;
    } else {
      fov = float(2 * std::atan(std::sqrt(36.0 * 36 + 24 * 24) / (2 * focal_mm)) * 180 / M_PI);
      axis = FovAxis::kDiagonal;
    }
  } else {
    fov = float(p.FloatIn("fov", 45, 1e-4, 179.9));
    axis = axes.at(p.Choice("fov_axis", "x", {"x", "y", "diagonal", "smaller", "larger"}));
    Vec2f t = ScreenTangents(fov, axis, w, h);
    focal_mm = sensor_width / (2 * t.x);
  }
  if (!thin) return std::make_unique<PerspectiveCamera>(b.to_world, w, h, fov, axis, near_clip, b.far_clip);
  float radius;
  if (p.Has("fnumber")) {
    if (p.Has("aperture_radius")) throw ErrorAt(p.LocOf("fnumber"), "give either fnumber or aperture_radius");
    // Aperture diameter = focal length / N; the focal length in scene units (metres).
    radius = float(focal_mm * 1e-3 / (2 * p.FloatIn("fnumber", 2.8, 0.1, 1e4)));
  } else {
    radius = float(p.FloatIn("aperture_radius", 0.1, 0, 1e30));
  }
  float focus = float(p.FloatIn("focus_distance", 0, 1e-6, 1e30));
  if (!p.Has("focus_distance")) throw ErrorAt(p.loc(), "thinlens needs the property 'focus_distance'");
  int blades = int(p.IntIn("blades", 0, 0, 64));
  if (blades == 1 || blades == 2) throw ErrorAt(p.LocOf("blades"), "blades must be 0 (circular) or at least 3");
  return std::make_unique<ThinLensCamera>(b.to_world, w, h, fov, axis, near_clip, b.far_clip, radius, focus, blades,
                                          float(p.Float("blade_rotation", 0)));
}

using SensorFactory = std::function<std::unique_ptr<Camera>(const Properties&, const SensorBase&)>;

const std::map<std::string, SensorFactory>& SensorRegistry() {
  static const std::map<std::string, SensorFactory> registry = {
      {"perspective", [](const Properties& p, const SensorBase& b) { return BuildPerspective(p, b, false); }},
      {"thinlens", [](const Properties& p, const SensorBase& b) { return BuildPerspective(p, b, true); }},
      {"orthographic",
       [](const Properties& p, const SensorBase& b) -> std::unique_ptr<Camera> {
         return std::make_unique<OrthographicCamera>(b.to_world, b.width, b.height, NearClip(p, b.far_clip), b.far_clip);
       }},
      {"realistic",
       [](const Properties& p, const SensorBase& b) {
         return BuildLensCamera(p, b.to_world, b.width, b.height, b.far_clip);
       }},
  };
  return registry;
}

}  // namespace

void BuildSensor(const ObjectNode& node, RenderSetup& setup) {
  const auto& registry = SensorRegistry();
  auto it = registry.find(node.type);
  if (it == registry.end()) UnknownType(node, registry);
  Properties p(node);
  const ObjectNode* film = OneChild(p, "film");
  setup.film = BuildFilm(film);
  setup.film.loc = film ? film->loc : node.loc;
  setup.sampler = BuildSamplerSettings(OneChild(p, "sampler"));
  SensorBase base{p.GetTransform("to_world"), setup.film.width, setup.film.height,
                  float(p.FloatIn("far_clip", 1e4, 1e-30, 1e30))};
  CheckWithinSceneLimit(base.to_world.Point(Vec3f(0.f)), p.LocOf("to_world"), "the sensor");
  setup.camera = it->second(p, base);
  p.WarnUnused();
}

std::unique_ptr<Integrator> BuildIntegrator(const ObjectNode* node, const Scene& scene) {
  if (!node) return std::make_unique<PathIntegrator>(scene, -1, 5);
  using IntegratorFactory = std::function<std::unique_ptr<Integrator>(const Properties&, const Scene&)>;
  static const std::map<std::string, IntegratorFactory> registry = {
      {"path",
       [](const Properties& p, const Scene& scene) -> std::unique_ptr<Integrator> {
         int max_depth = int(p.IntIn("max_depth", -1, -1, 1 << 20));
         if (max_depth == 0) throw ErrorAt(p.LocOf("max_depth"), "max_depth must be -1 (unbounded) or at least 1");
         return std::make_unique<PathIntegrator>(scene, max_depth, int(p.IntIn("rr_depth", 5, 1, 1 << 20)));
       }},
      {"direct",
       [](const Properties& p, const Scene& scene) -> std::unique_ptr<Integrator> {
         int shading = int(p.IntIn("shading_samples", 1, 0, 1 << 16));
         return std::make_unique<DirectIntegrator>(scene, int(p.IntIn("emitter_samples", shading, 0, 1 << 16)),
                                                   int(p.IntIn("bsdf_samples", shading, 0, 1 << 16)));
       }},
  };
  auto it = registry.find(node->type);
  if (it == registry.end()) UnknownType(*node, registry);
  Properties p(*node);
  std::unique_ptr<Integrator> integrator = it->second(p, scene);
  p.WarnUnused();
  return integrator;
}

}  // namespace objektiv
