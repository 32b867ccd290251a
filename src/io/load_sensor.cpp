// The <sensor> plugins: perspective, thinlens, orthographic (realistic: load_lens_sensor.cpp).
#include <cmath>

#include "io/loader_context.h"

namespace objektiv {
namespace {

// Mitsuba's focal_length: "50mm" (or a number) on a 36 x 24 mm film, measured on the diagonal.
double FocalLengthMm(const Properties& p) {
  const Location at = p.LocOf("focal_length");
  double f;
  if (p.TypeOf("focal_length") == ValueType::kString) {
    std::string s = p.String("focal_length");
    if (s.size() > 2 && s.substr(s.size() - 2) == "mm") s = s.substr(0, s.size() - 2);
    char* end = nullptr;
    f = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || *end != '\0') throw ErrorAt(at, "focal_length '{}' is not a length like \"50mm\"", s);
  } else {
    f = p.Float("focal_length");
  }
  if (!(f > 0)) throw ErrorAt(at, "focal_length must be positive");
  return f;
}

// The clip planes, read only by the sensors that use them (the realistic camera starts its
// rays at the lens's front, so near_clip would be ignored there: it is warned about).
float NearClip(const Properties& p, float far_clip) {
  float near_clip = float(p.FloatIn("near_clip", 1e-2, 0, 1e30));
  if (!(far_clip > near_clip)) throw ErrorAt(p.LocOf("far_clip"), "far_clip must exceed near_clip");
  return near_clip;
}

constexpr Named<FovAxis> kFovAxes[] = {{"x", FovAxis::kX},
                                       {"y", FovAxis::kY},
                                       {"diagonal", FovAxis::kDiagonal},
                                       {"smaller", FovAxis::kSmaller},
                                       {"larger", FovAxis::kLarger}};

const std::vector<PropertyDecl> kPerspectiveProperties = {{"near_clip", PropType::kFloat},
                                                          {"fov", PropType::kFloat},
                                                          {"fov_axis", kFovAxes},
                                                          {"focal_length", PropType::kFloatOrString},
                                                          {"sensor_width", PropType::kFloat}};
const std::vector<PropertyDecl> kThinLensProperties =
    Join(kPerspectiveProperties, {{"aperture_radius", PropType::kFloat},
                                  {"fnumber", PropType::kFloat},
                                  {"focus_distance", PropType::kFloat},
                                  {"blades", PropType::kInteger},
                                  {"blade_rotation", PropType::kFloat}});

std::unique_ptr<Camera> BuildPerspective(const Properties& p, const SensorBase& b, bool thin) {
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
    axis = p.Choice("fov_axis", FovAxis::kX, kFovAxes);
    Vec2f t = ScreenTangents(fov, axis, w, h);
    focal_mm = sensor_width / (2 * t.x);
  }
  // A stereo eye: moved along the camera's x axis, its frustum shifted toward the convergence plane.
  const Transform to_world = EyeTransform(b.to_world, b.eye.offset);
  const float shift = b.eye.OffAxis() ? EyeFrustumShift(b.to_world, b.eye.offset, b.eye.convergence) : 0.f;
  if (!thin) {
    auto camera = std::make_unique<PerspectiveCamera>(to_world, w, h, fov, axis, near_clip, b.far_clip);
    camera->ShiftFrustum(Vec2f(shift, 0.f));
    return camera;
  }
  float radius;
  if (p.Has("fnumber")) {
    if (p.Has("aperture_radius")) throw ErrorAt(p.LocOf("fnumber"), "give either fnumber or aperture_radius");
    // Aperture diameter = focal length / N; the focal length in scene units (metres).
    radius = float(focal_mm * 1e-3 / (2 * p.FloatIn("fnumber", 2.8, 0.1, 1e4)));
  } else {
    radius = float(p.FloatIn("aperture_radius", 0.1, 0, 1e30));
  }
  if (!p.Has("focus_distance")) throw ErrorAt(p.loc(), "thinlens needs the property 'focus_distance'");
  float focus = float(p.FloatIn("focus_distance", 0, 1e-6, 1e30));
  int blades = int(p.IntIn("blades", 0, 0, 64));
  if (blades == 1 || blades == 2) throw ErrorAt(p.LocOf("blades"), "blades must be 0 (circular) or at least 3");
  auto camera = std::make_unique<ThinLensCamera>(to_world, w, h, fov, axis, near_clip, b.far_clip, radius, focus, blades,
                                                 float(p.Float("blade_rotation", 0)));
  camera->ShiftFrustum(Vec2f(shift, 0.f));
  return camera;
}

}  // namespace

const SensorRegistry& SensorPlugins() {
  static const SensorRegistry registry(
      "sensor",
      {{"to_world", PropType::kTransform},
       {"far_clip", PropType::kFloat},
       {"film", PropType::kObject},
       {"sampler", PropType::kObject},
       {"medium", PropType::kMedium}},
      {
          {"perspective", kPerspectiveProperties,
           [](const Properties& p, const SensorBase& b) { return BuildPerspective(p, b, false); }},
          {"thinlens", kThinLensProperties,
           [](const Properties& p, const SensorBase& b) { return BuildPerspective(p, b, true); }},
          {"orthographic",
           {{"near_clip", PropType::kFloat}},
           [](const Properties& p, const SensorBase& b) -> std::unique_ptr<Camera> {
             // A stereo eye turns toward the convergence plane (stereo_camera.h: OrthographicEyeTransform).
             const Transform to_world = b.eye.offset == 0 ? b.to_world
                                        : OrthographicEyeTransform(b.to_world, b.eye.offset, b.eye.convergence);
             return std::make_unique<OrthographicCamera>(to_world, b.width, b.height, NearClip(p, b.far_clip),
                                                         b.far_clip);
           }},
          RealisticSensorPlugin(),
          StereoSensorPlugin(),
      });
  return registry;
}

void BuildSensor(const ObjectNode& node, LoaderContext& ctx, RenderSetup& setup) {
  const GlassCatalog& glasses = ctx.glasses;
  const SensorRegistry& registry = SensorPlugins();
  const SensorRegistry::PluginType& plugin = registry.Find(node);
  Properties p = registry.Open(node, plugin);
  const ObjectNode* film = OneChild(p, "film");
  setup.film = BuildFilm(film);
  setup.film.loc = film ? film->loc : node.loc;
  setup.sampler = BuildSamplerSettings(OneChild(p, "sampler"));
  SensorBase base{p.GetTransform("to_world"), setup.film.width, setup.film.height,
                  float(p.FloatIn("far_clip", 1e4, 1e-30, 1e30)), &glasses};
  CheckWithinSceneLimit(base.to_world.Point(Vec3f(0.f)), p.LocOf("to_world"), "the sensor");
  setup.camera = plugin.make(p, base);
  ctx.scene.SetCameraMedium(MediumProperty(p, "medium", ctx));
  p.WarnUnused();
  // A camera that tiles the film with several images (stereo) takes the film as one image's
  // size and makes it larger; a crop window of it would be ambiguous (--crop crops the whole).
  if (setup.camera->width() != setup.film.width || setup.camera->height() != setup.film.height) {
    const CropWindow whole{0, 0, setup.film.width, setup.film.height};
    if (!(setup.film.crop == whole))
      throw ErrorAt(setup.film.loc, "the film of a '{}' sensor is one eye's image and cannot be cropped (crop_*); "
                    "crop the whole {}x{} film with --crop", node.type, setup.camera->width(), setup.camera->height());
    setup.film.width = setup.camera->width(), setup.film.height = setup.camera->height();
    setup.film.crop = {0, 0, setup.film.width, setup.film.height};
  }
}

std::unique_ptr<Camera> BuildCamera(const ObjectNode& node, int width, int height, const GlassCatalog& glasses) {
  const SensorRegistry& registry = SensorPlugins();
  const SensorRegistry::PluginType& plugin = registry.Find(node);
  Properties p = registry.Open(node, plugin);
  SensorBase base{p.GetTransform("to_world"), width, height, float(p.FloatIn("far_clip", 1e4, 1e-30, 1e30)), &glasses};
  CheckWithinSceneLimit(base.to_world.Point(Vec3f(0.f)), p.LocOf("to_world"), "the sensor");
  return plugin.make(p, base);
}

}  // namespace objektiv
