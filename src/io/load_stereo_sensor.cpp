// Builder for <sensor type="stereo">: a stereo rig of the one nested <sensor> (any type but
// stereo), built twice, once per eye (camera/stereo_camera.h). The rig's <film> is one eye's
// image; its <sampler> the render's. The nested sensor says where the rig is (to_world) and
// what each eye is; it has no film or sampler of its own.
#include "base/log.h"
#include "camera/realistic_camera.h"
#include "camera/stereo_camera.h"
#include "io/loader_context.h"

namespace objektiv {

namespace {

constexpr Named<bool> kFrusta[] = {{"offaxis", true}, {"parallel", false}};
constexpr Named<StereoLayout> kLayouts[] = {{"side-by-side", StereoLayout::kSideBySide},
                                            {"over-under", StereoLayout::kOverUnder},
                                            {"anaglyph", StereoLayout::kAnaglyph}};

// While the second eye is built, only errors are logged: it would repeat what the first said.
class QuietLog {
 public:
  QuietLog() : level_(spdlog::get_level()) { spdlog::set_level(spdlog::level::err); }
  ~QuietLog() { spdlog::set_level(level_); }
  QuietLog(const QuietLog&) = delete;
  QuietLog& operator=(const QuietLog&) = delete;

 private:
  spdlog::level::level_enum level_;
};

// One eye of the nested sensor `in` (its plugin `plugin`), `eye` as the rig places it.
std::unique_ptr<Camera> BuildEye(const ObjectNode& in, const SensorBase& rig, const StereoEye& eye) {
  const SensorRegistry& registry = SensorPlugins();
  const SensorRegistry::PluginType& plugin = registry.Find(in);
  Properties p = registry.Open(in, plugin);
  for (const char* tag : {"film", "sampler"})
    if (const ObjectNode* child = OneChild(p, tag))
      throw ErrorAt(child->loc, "the <{}> of a stereo rig belongs in the stereo sensor, not in the sensor it wraps", tag);
  SensorBase b{p.GetTransform("to_world"), rig.width, rig.height, float(p.FloatIn("far_clip", 1e4, 1e-30, 1e30)),
               rig.glasses, eye};
  CheckWithinSceneLimit(b.to_world.Point(Vec3f(0.f)), p.LocOf("to_world"), "the sensor");
  std::unique_ptr<Camera> camera = plugin.make(p, b);
  // The lens's ghosts, glare and diffraction are passes over one lens's whole film.
  if (const auto* real = dynamic_cast<const RealisticCamera*>(camera.get()); real && real->effects().Any()) {
    const char* name = real->effects().ghosts ? "ghosts" : "diffraction";
    throw ErrorAt(p.LocOf(name), "{} in a stereo rig: the lens's ghosts, glare and diffraction are not rendered per "
                  "eye; render each eye with its own realistic sensor for them", name);
  }
  p.WarnUnused();
  return camera;
}

std::unique_ptr<Camera> BuildStereo(const Properties& p, const SensorBase& b) {
  for (const char* name : {"to_world", "far_clip"})
    if (p.Has(name))
      throw ErrorAt(p.LocOf(name), "stereo: give {} to the nested <sensor> (the rig is that camera, its eyes beside it)",
                    name);
  const std::vector<std::shared_ptr<ObjectNode>> inner = p.Children("sensor");
  if (inner.size() != 1) throw ErrorAt(p.loc(), "stereo needs exactly one nested <sensor>, got {}", inner.size());
  const ObjectNode& in = *inner[0];
  if (in.type == "stereo") throw ErrorAt(in.loc, "a stereo sensor cannot wrap another stereo sensor");
  const double separation = p.Float("eye_separation", 0.065);
  if (!(separation > 0 && separation < 1e6))
    throw ErrorAt(p.LocOf("eye_separation"), "eye_separation must be a distance above 0 and below 1e6 (metres), got {}",
                  separation);
  const bool offaxis = p.Choice("frustum", true, kFrusta);
  const StereoLayout layout = p.Choice("layout", StereoLayout::kSideBySide, kLayouts);
  double convergence = 0;
  if (offaxis) {
    if (!p.Has("convergence_distance"))
      throw ErrorAt(p.loc(), "stereo with frustum 'offaxis' needs convergence_distance (metres: the plane on which "
                    "both eyes' images coincide)");
    convergence = p.Float("convergence_distance");
    if (!(convergence > 0 && convergence < 1e30))
      throw ErrorAt(p.LocOf("convergence_distance"), "convergence_distance must be a distance above 0 and below 1e30 (metres), got {}",
                    convergence);
  } else if (in.type == "orthographic") {
    throw ErrorAt(p.LocOf("frustum"), "an orthographic camera moved sideways sees the same picture, shifted: with "
                  "frustum 'parallel' its eyes would show no depth; use 'offaxis' (the eyes turn toward the "
                  "convergence plane)");
  } else if (p.Has("convergence_distance")) {
    spdlog::warn("{}:{}: convergence_distance does nothing with frustum 'parallel' (the frusta are not shifted)",
                 p.LocOf("convergence_distance").file, p.LocOf("convergence_distance").line);
  }
  // The left eye at +x (the camera's left), the right one at -x.
  std::unique_ptr<Camera> left = BuildEye(in, b, {separation / 2, convergence});
  std::unique_ptr<Camera> right;
  {
    QuietLog quiet;
    right = BuildEye(in, b, {-separation / 2, convergence});
  }
  return std::make_unique<StereoCamera>(std::move(left), std::move(right), layout);
}

}  // namespace

SensorRegistry::PluginType StereoSensorPlugin() {
  return {"stereo",
          {{"eye_separation", PropType::kFloat},
           {"convergence_distance", PropType::kFloat},
           {"frustum", kFrusta},
           {"layout", kLayouts},
           {"sensor", PropType::kObject}},
          BuildStereo};
}

}  // namespace objektiv
