// Builder for <sensor type="realistic">: a camera with a real lens prescription.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "base/log.h"
#include "base/text_file.h"
#include "camera/lens_camera_setup.h"
#include "camera/realistic_camera.h"
#include "io/image_io.h"
#include "io/loader_context.h"
#include "optics/anamorphic.h"
#include "optics/coating_library.h"
#include "optics/paraxial.h"
#include "optics/lens_file.h"
#include "optics/undispersed_lens.h"

namespace objektiv {

namespace {

struct SensorFormat {
  const char* name;
  double width, height;  // mm
};
// Named sensor formats (the usual nominal sizes).
constexpr SensorFormat kSensorFormats[] = {
    {"full_frame", 36, 24}, {"35mm", 36, 24},           {"aps-h", 28.7, 19.0},
    {"aps-c", 23.6, 15.7},  {"super35", 24.89, 18.66},  {"micro_four_thirds", 17.3, 13.0},
    {"medium_format", 43.8, 32.9},
};

// A format name compared without case, spaces, hyphens or underscores ("Super 35" = "super35").
std::string FormatKey(const std::string& name) {
  std::string key;
  for (char c : name)
    if (c != ' ' && c != '-' && c != '_') key += char(std::tolower(static_cast<unsigned char>(c)));
  return key;
}

constexpr Named<LensModel> kLensModels[] = {
    {"real", LensModel::kReal}, {"thick", LensModel::kThick}, {"thin", LensModel::kThin}};
constexpr Named<DiffractionScope> kDiffractionScopes[] = {
    {"off", DiffractionScope::kOff}, {"emitters", DiffractionScope::kEmitters}, {"image", DiffractionScope::kImage}};
constexpr Named<Vignetting> kVignettingModes[] = {{"full", Vignetting::kFull},
                                                  {"cos4", Vignetting::kNatural},
                                                  {"aperture", Vignetting::kOptical},
                                                  {"none", Vignetting::kNone}};

// A lens file relative to the scene, or a shipped lens by name (see ResolveLens).
LensPrescription LoadSceneLens(const Properties& p, const GlassCatalog& glasses) {
  std::string name = p.String("lens");
  const Location& loc = p.LocOf("lens");
  std::string path;
  try {
    path = ResolveLens(name, std::filesystem::path(loc.file).parent_path().string());
  } catch (const InputError& e) {
    throw ErrorAt(loc, "{}", e.what());
  }
  try {
    return ReadLensFile(path, glasses);
  } catch (const InputError& e) {  // the lens file's own file:line, after the scene's
    throw ErrorAt(loc, "lens '{}': {}", name, e.what());
  }
}

// The coating property (optics/coating_library.h: Recoat).
void RecoatAsAsked(const Properties& p, LensPrescription& lens) {
  if (!p.Has("coating")) return;
  const std::string name = p.String("coating");  // its own errors name the line already
  try {
    Recoat(lens, CoatingForLens(name, lens));
  } catch (const InputError& e) {
    throw ErrorAt(p.LocOf("coating"), "{}", e.what());
  }
}

// The sensor's size; the image takes the largest centred rectangle of it with the image's
// aspect, or where it is desqueezed, with that aspect over the squeeze (its pixels are then
// `squeeze` times taller than wide on the film).
Vec2d SensorSize(const Properties& p, int width, int height, double squeeze) {
  double w = 36, h = 24;
  if (p.Has("sensor")) {
    if (p.Has("sensor_width") || p.Has("sensor_height"))
      throw ErrorAt(p.LocOf("sensor"), "give either sensor or sensor_width/sensor_height, not both");
    std::string name = p.String("sensor"), key = FormatKey(name);
    bool found = false;
    std::string known;
    for (const SensorFormat& f : kSensorFormats) {
      if (!known.empty()) known += ", ";
      known += f.name;
      if (key == FormatKey(f.name)) w = f.width, h = f.height, found = true;
    }
    if (!found) throw ErrorAt(p.LocOf("sensor"), "unknown sensor '{}' (known: {})", name, known);
  } else {
    // Neither given: the full frame (36 x 24 mm). A width alone: the film's aspect.
    w = p.FloatIn("sensor_width", 36, 1e-3, 1e4);
    h = p.Has("sensor_height") ? p.FloatIn("sensor_height", 24, 1e-3, 1e4) : p.Has("sensor_width") ? w * height / width : 24;
  }
  double aspect = double(width) / height / squeeze;
  return w / h > aspect ? Vec2d(h * aspect, h) : Vec2d(w, w / aspect);
}

// A tilt-shift lens's tilt (tilt_x, tilt_y: degrees, right-handed about the film's x and y
// axes, x then y): the whole lens turned about its entrance pupil once its stop is set
// (optics/lens_setup.h), the film where it was; the plane of focus tilts with it (Scheimpflug).
std::optional<SurfacePlacement> Tilt(const Properties& p) {
  const double ax = p.FloatIn("tilt_x", 0, -45, 45), ay = p.FloatIn("tilt_y", 0, -45, 45);
  if (ax == 0 && ay == 0) return std::nullopt;
  return SurfacePlacement::DecenterTilt(0, 0, ax, ay, 0);
}

// How much the picture is stretched horizontally (an anamorphic lens's squeeze undone): the
// number given, or "lens" for the lens's own squeeze (optics/anamorphic.h); 1 where not given.
double Desqueeze(const Properties& p, const LensPrescription& lens) {
  if (!p.Has("desqueeze")) return 1;
  const std::string value = p.String("desqueeze");
  if (value != "lens") {
    char* end = nullptr;
    const double factor = std::strtod(value.c_str(), &end);
    if (value.empty() || end != value.c_str() + value.size() || !(factor >= 0.1 && factor <= 10))
      throw ErrorAt(p.LocOf("desqueeze"), "desqueeze '{}': a factor from 0.1 to 10, or \"lens\" for the lens's squeeze",
                    Printable(value));
    return factor;
  }
  if (!lens.HasToroids())
    throw ErrorAt(p.LocOf("desqueeze"), "desqueeze=\"lens\": {} is not anamorphic (it has no toroidal surface); give a "
                  "number to stretch the picture anyway", lens.name);
  const double squeeze = ComputeAnamorphosis(lens, ComputeParaxial(lens)).squeeze;
  if (!(squeeze >= 0.1 && squeeze <= 10))
    throw ErrorAt(p.LocOf("desqueeze"), "desqueeze=\"lens\": the squeeze of {} is {:.4g}, outside 0.1 to 10", lens.name, squeeze);
  spdlog::info("{}:{}: desqueezed by the lens's squeeze, {:.4f}", p.LocOf("desqueeze").file, p.LocOf("desqueeze").line, squeeze);
  return squeeze;
}

// A lens shift that moves the film's corners past the lens's image circle leaves them black
// (the pupil bounds know where no light passes): say so.
void WarnIfShiftedPastTheImageCircle(const Properties& p, const LensCameraSettings& s, const Camera& camera) {
  const auto* real = dynamic_cast<const RealisticCamera*>(&camera);
  if (!real || (s.shift.x == 0 && s.shift.y == 0)) return;
  const double corner = std::hypot(s.sensor_width / 2 + std::abs(s.shift.x), s.sensor_height / 2 + std::abs(s.shift.y));
  if (real->bounds().BoundAt(Vec2d(corner, 0))) return;
  // Corners dark without the shift too (a circular fisheye's frame): not the shift's doing.
  if (!real->bounds().BoundAt(Vec2d(std::hypot(s.sensor_width, s.sensor_height) / 2, 0))) return;
  double circle = 0;  // the largest film radius light reaches, to a thousandth of the corner's
  for (int k = 999; k > 0 && circle == 0; --k)
    if (real->bounds().BoundAt(Vec2d(corner * k / 1000, 0))) circle = corner * k / 1000;
  const Location& at = p.LocOf(p.Has("shift_x") ? "shift_x" : "shift_y");
  spdlog::warn("{}:{}: the lens shift ({}, {}) mm puts the film's corners {:.1f} mm from the lens's axis, beyond its "
               "image circle ({:.1f} mm radius): no light reaches them",
               at.file, at.line, s.shift.x, s.shift.y, corner, circle);
}

// Ghosts and diffraction (camera/lens_effects.h); their tuning is said to do nothing without them.
LensEffects ReadLensEffects(const Properties& p, LensModel model) {
  LensEffects e;
  e.ghosts = p.Bool("ghosts", false);
  e.ghost_grid = int(p.IntIn("ghost_grid", 32, 4, 512));
  e.ghost_cull = p.FloatIn("ghost_cull", 1e-3, 0, 0.5);  // more would leave out most of the ghosts' light
  e.glare_samples = int(p.IntIn("glare_samples", 4, 0, 65536));
  e.wavelengths = int(p.IntIn("flare_wavelengths", 16, 1, 64));
  e.diffraction = p.Choice("diffraction", DiffractionScope::kOff, kDiffractionScopes);
  auto warn = [&p](const char* name, const char* why) {
    if (p.Has(name)) spdlog::warn("{}:{}: {} does nothing {}", p.LocOf(name).file, p.LocOf(name).line, name, why);
  };
  if (!e.ghosts) {
    warn("ghost_grid", "without ghosts true");
    warn("ghost_cull", "without ghosts true");
    warn("glare_samples", "without ghosts true");
  }
  if (!e.Any()) warn("flare_wavelengths", "without ghosts or diffraction");
  if (model != LensModel::kReal && e.Any()) {
    for (const char* name : {"ghosts", "diffraction"})
      if (name == std::string("ghosts") ? e.ghosts : e.diffraction != DiffractionScope::kOff)
        spdlog::warn("{}:{}: {} needs lens_model 'real' (the ghosts and the diffraction come from the lens's surfaces "
                     "and its exit pupil): ignored",
                     p.LocOf(name).file, p.LocOf(name).line, name);
    return {};
  }
  return e;
}

// A lens hood (optics/lens_hood.h): hood_length with hood_diameter (round) or hood_width and
// hood_height (rectangular, along the film's sides), mm.
std::optional<LensHood> Hood(const Properties& p, LensModel model) {
  const bool round = p.Has("hood_diameter"), box = p.Has("hood_width") || p.Has("hood_height");
  if (!p.Has("hood_length")) {
    for (const char* name : {"hood_diameter", "hood_width", "hood_height"})
      if (p.Has(name)) throw ErrorAt(p.LocOf(name), "{} without hood_length (mm from the front vertex to the mouth)", name);
    return std::nullopt;
  }
  if (round == box)
    throw ErrorAt(p.LocOf("hood_length"), "a hood's mouth is hood_diameter (round) or hood_width and hood_height (rectangular)");
  if (box && !(p.Has("hood_width") && p.Has("hood_height")))
    throw ErrorAt(p.LocOf(p.Has("hood_width") ? "hood_width" : "hood_height"), "a rectangular hood takes both hood_width and hood_height");
  if (model != LensModel::kReal) {
    spdlog::warn("{}:{}: the hood needs lens_model 'real' (it lies in front of the lens's first element): ignored",
                 p.LocOf("hood_length").file, p.LocOf("hood_length").line);
    return std::nullopt;
  }
  LensHood h;
  h.length = p.FloatIn("hood_length", 0, 1e-3, 1e5);
  if (round) h.radius = 0.5 * p.FloatIn("hood_diameter", 0, 1e-3, 1e5);
  else h.half_width = 0.5 * p.FloatIn("hood_width", 0, 1e-3, 1e5), h.half_height = 0.5 * p.FloatIn("hood_height", 0, 1e-3, 1e5);
  return h;
}

// The camera a <sensor type="realistic"> describes.
std::unique_ptr<Camera> BuildLensCamera(const Properties& p, const SensorBase& b) {
  LensCameraSpec spec;
  spec.lens = LoadSceneLens(p, *b.glasses);
  // The prescription scaled as a whole to another focal length (radii, thicknesses, apertures).
  if (p.Has("focal_length")) spec.lens = ScaledToFocalLength(spec.lens, p.FloatIn("focal_length", 50, 1e-3, 1e6));
  RecoatAsAsked(p, spec.lens);
  spec.tilt = Tilt(p);
  spec.model = p.Choice("lens_model", LensModel::kReal, kLensModels);
  if (!p.Bool("dispersion", true)) {
    if (KeepsDispersionWithout(spec.lens))
      spdlog::warn("{}:{}: dispersion false makes the lens's glasses constant at their d-line index; its gradient-index "
                   "and crystal media keep their dispersion", p.LocOf("dispersion").file, p.LocOf("dispersion").line);
    spec.lens = WithoutDispersion(spec.lens);
  }
  if (p.Has("fnumber") && p.Has("aperture_diameter"))
    throw ErrorAt(p.LocOf("aperture_diameter"), "give either fnumber or aperture_diameter, not both");
  if (p.Has("fnumber")) spec.fnumber = p.FloatIn("fnumber", 0, 0.1, 1e4);
  if (p.Has("aperture_diameter")) spec.stop_diameter = p.FloatIn("aperture_diameter", 0, 1e-6, 1e6);
  spec.blades = int(p.IntIn("blades", 0, 0, 64));
  if (spec.blades == 1 || spec.blades == 2) throw ErrorAt(p.LocOf("blades"), "blades must be 0 (circular) or at least 3");
  spec.blade_curvature = p.FloatIn("blade_curvature", 0, 0, 1);
  spec.blade_rotation = p.Float("blade_rotation", 0);
  if (p.Has("focus_point")) {
    if (p.Has("focus_distance")) throw ErrorAt(p.LocOf("focus_point"), "give either focus_distance or focus_point");
    Vec3d f = p.Point("focus_point", Vec3d(0, 0, 0));
    spec.focus_point = Vec3f(float(f.x), float(f.y), float(f.z));
  }
  spec.focus_distance = p.FloatIn("focus_distance", INFINITY, 1e-6, INFINITY);
  LensCameraSettings& s = spec.settings;
  Vec2d sensor = SensorSize(p, b.width, b.height, Desqueeze(p, spec.lens));
  s.sensor_width = sensor.x, s.sensor_height = sensor.y;
  s.shift = Vec2d(p.FloatIn("shift_x", 0, -1e4, 1e4), p.FloatIn("shift_y", 0, -1e4, 1e4));
  s.metres_per_unit = p.FloatIn("metres_per_unit", 1, 1e-12, 1e12);
  s.exposure_scale = p.FloatIn("exposure_scale", 1, 0, 1e30);
  s.vignetting = p.Choice("vignetting", Vignetting::kFull, kVignettingModes);
  s.transmission = p.Bool("transmission", true);
  s.spectral_mis = p.Bool("spectral_mis", true);
  // The ideal models have no glass and no rims: what only the real lens has is said to do nothing.
  if (spec.model != LensModel::kReal) {
    const char* model = spec.model == LensModel::kThick ? "thick" : "thin";
    if (p.Has("coating"))
      spdlog::warn("{}:{}: coating does nothing with lens_model '{}', which has no glass surfaces",
                   p.LocOf("coating").file, p.LocOf("coating").line, model);
    if (p.Has("dispersion"))
      spdlog::warn("{}:{}: dispersion does nothing with lens_model '{}', whose rays do not depend on the wavelength",
                   p.LocOf("dispersion").file, p.LocOf("dispersion").line, model);
    if (p.Has("transmission"))
      spdlog::warn("{}:{}: transmission (the real lens's Fresnel and glass losses) does nothing with lens_model '{}', "
                   "which has no glass",
                   p.LocOf("transmission").file, p.LocOf("transmission").line, model);
    if (p.Has("spectral_mis"))
      spdlog::warn("{}:{}: spectral_mis (for a real lens's dispersive glass) does nothing with lens_model '{}', whose rays "
                   "do not depend on the wavelength",
                   p.LocOf("spectral_mis").file, p.LocOf("spectral_mis").line, model);
    if (s.vignetting == Vignetting::kOptical)
      spdlog::warn("{}:{}: lens_model '{}' has no rims and so no optical vignetting: vignetting 'aperture' gives what "
                   "'none' does",
                   p.LocOf("vignetting").file, p.LocOf("vignetting").line, model);
  }
  s.far_clip = b.far_clip;
  spec.hood = Hood(p, spec.model);
  if (spec.hood)
    if (std::string why = spec.hood->Mismatch(spec.lens.surfaces.front()); !why.empty())
      throw ErrorAt(p.LocOf(p.Has("hood_diameter") ? "hood_diameter" : "hood_width"), "{}", why);
  if (p.Has("aperture_mask")) {
    std::string path = ResolvePath(p.LocOf("aperture_mask"), p.String("aperture_mask"));
    try {
      s.aperture_mask = std::make_shared<ApertureMask>(ReadImageRgb(path, /*raw=*/true));
    } catch (const InputError& e) {
      throw ErrorAt(p.LocOf("aperture_mask"), "{}", e.what());
    }
  }
  // A stereo eye (camera/stereo_camera.h): moved along the camera's x axis (metres, in scene
  // units by metres_per_unit) and its sensor shifted toward the convergence plane.
  spec.eye_offset_mm = b.eye.offset * 1e3;
  spec.convergence_mm = b.eye.convergence * 1e3;
  const Transform to_world = EyeTransform(b.to_world, b.eye.offset / s.metres_per_unit);
  std::unique_ptr<Camera> camera;
  try {
    camera = MakeLensCamera(to_world, b.width, b.height, spec);
  } catch (const InputError& e) {
    throw ErrorAt(p.loc(), "{}", e.what());
  }
  WarnIfShiftedPastTheImageCircle(p, s, *camera);
  const LensEffects effects = ReadLensEffects(p, spec.model);
  // What the bundles cannot leave out.
  if (effects.Any() && s.vignetting != Vignetting::kFull)
    spdlog::warn("{}:{}: the lights' own images and their ghosts keep the lens's vignetting (the rims and the cos^4 "
                 "falloff) whatever vignetting says; only the camera rays follow it",
                 p.LocOf("vignetting").file, p.LocOf("vignetting").line);
  if (!s.transmission && p.Has("coating") && spec.model == LensModel::kReal)
    spdlog::warn("{}:{}: coating {} with transmission false (the surfaces' losses are not applied to the image)",
                 p.LocOf("coating").file, p.LocOf("coating").line,
                 effects.ghosts ? "changes only the ghosts and the glare" : "does nothing");
  if (effects.ghosts && !s.transmission)
    spdlog::warn("{}:{}: ghosts are made of the surfaces' reflections: with transmission false they keep them (and the "
                 "other surfaces' losses); the lights' own images leave the losses out as the camera rays do",
                 p.LocOf("transmission").file, p.LocOf("transmission").line);
  if (auto* real = dynamic_cast<RealisticCamera*>(camera.get())) real->SetEffects(effects);
  return camera;
}

}  // namespace

SensorRegistry::PluginType RealisticSensorPlugin() {
  return {"realistic",
          {{"lens", PropType::kString},
           {"focal_length", PropType::kFloat},
           {"lens_model", kLensModels},
           {"fnumber", PropType::kFloat},
           {"aperture_diameter", PropType::kFloat},
           {"blades", PropType::kInteger},
           {"blade_curvature", PropType::kFloat},
           {"blade_rotation", PropType::kFloat},
           {"focus_point", PropType::kPoint},
           {"focus_distance", PropType::kFloat},
           {"sensor", PropType::kString},
           {"sensor_width", PropType::kFloat},
           {"sensor_height", PropType::kFloat},
           {"desqueeze", PropType::kString},
           {"tilt_x", PropType::kFloat},
           {"tilt_y", PropType::kFloat},
           {"shift_x", PropType::kFloat},
           {"shift_y", PropType::kFloat},
           {"metres_per_unit", PropType::kFloat},
           {"exposure_scale", PropType::kFloat},
           {"vignetting", kVignettingModes},
           {"transmission", PropType::kBoolean},
           {"spectral_mis", PropType::kBoolean},
           {"dispersion", PropType::kBoolean},
           {"coating", PropType::kString},
           {"aperture_mask", PropType::kString},
           {"hood_length", PropType::kFloat},
           {"hood_diameter", PropType::kFloat},
           {"hood_width", PropType::kFloat},
           {"hood_height", PropType::kFloat},
           {"ghosts", PropType::kBoolean},
           {"ghost_grid", PropType::kInteger},
           {"glare_samples", PropType::kInteger},
           {"ghost_cull", PropType::kFloat},
           {"flare_wavelengths", PropType::kInteger},
           {"diffraction", kDiffractionScopes}},
          BuildLensCamera};
}

}  // namespace objektiv
