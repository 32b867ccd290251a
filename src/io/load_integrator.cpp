// The <integrator> plugins: each makes an Integrator from its properties.
#include "io/loader_context.h"

#include <cmath>
#include <limits>
#include "render/aov.h"
#include "render/light_tracer.h"
#include "render/sppm_integrator.h"
#include "render/whitted_integrator.h"

namespace objektiv {

namespace {

// max_depth and rr_depth as Mitsuba's path tracers take them (segments of the whole path).
struct PathDepths {
  int max_depth, rr_depth;
};
PathDepths ParsePathDepths(const Properties& p) {
  const int max_depth = int(p.IntIn("max_depth", -1, -1, 1 << 20));
  if (max_depth == 0)
    throw ErrorAt(p.LocOf("max_depth"), "integrator '{}': max_depth must be -1 (unbounded) or at least 1", p.type());
  return {max_depth, int(p.IntIn("rr_depth", 5, 1, 1 << 20))};
}

// Mitsuba's `aov`: the AOVs (render/aov.h) beside the image of the nested integrator (the path
// tracer when none is nested).
std::unique_ptr<Integrator> MakeAovIntegrator(const Properties& p, const Scene& scene) {
  std::vector<Aov> aovs;
  try {
    aovs = ParseAovs(p.String("aovs"));
  } catch (const std::invalid_argument& e) {
    throw ErrorAt(p.LocOf("aovs"), "aovs: {}", e.what());
  }
  auto nested = p.Children("integrator");
  if (nested.size() > 1) throw ErrorAt(nested[1]->loc, "aov takes one nested <integrator>, got {}", nested.size());
  std::unique_ptr<Integrator> inner =
      nested.empty() ? std::make_unique<PathIntegrator>(scene, -1, 5) : IntegratorPlugins().Build(*nested[0], scene);
  auto* camera_path = dynamic_cast<CameraPathIntegrator*>(inner.get());
  if (!camera_path) throw ErrorAt(nested[0]->loc, "aov needs an integrator of camera paths inside, not '{}'", nested[0]->type);
  if (dynamic_cast<AovIntegrator*>(inner.get())) throw ErrorAt(nested[0]->loc, "aov cannot wrap another aov");
  inner.release();
  return std::make_unique<AovIntegrator>(scene, std::move(aovs), std::unique_ptr<CameraPathIntegrator>(camera_path));
}

// The classic tracer (render/whitted_integrator.h).
std::unique_ptr<Integrator> MakeWhitted(const Properties& p, const Scene& scene) {
  WhittedSettings w;
  // Every branch is followed: the depth needs a bound, and the bailout a floor.
  w.max_depth = int(p.IntIn("max_depth", w.max_depth, 1, WhittedSettings::kMaxDepth));
  w.shadow_grid = int(p.IntIn("shadow_grid", w.shadow_grid, 1, 64));
  w.wavelength_sets = int(p.IntIn("wavelength_sets", w.wavelength_sets, 1, CameraPathIntegrator::kMaxWavelengthSets));
  w.bailout = float(p.FloatIn("bailout", w.bailout, WhittedSettings::kMinBailout, 1));
  if (auto ambient = p.SpectrumProp("ambient")) w.ambient = MakeSpectrum(*ambient, SpectrumUsage::kIlluminant);
  return std::make_unique<WhittedIntegrator>(scene, std::move(w));
}

// Stochastic progressive photon mapping (render/sppm_integrator.h).
std::unique_ptr<Integrator> MakeSppm(const Properties& p, const Scene& scene) {
  SppmSettings s;
  const PathDepths d = ParsePathDepths(p);
  s.max_depth = d.max_depth, s.rr_depth = d.rr_depth;
  s.photon_count = p.IntIn("photon_count", s.photon_count, 1, SppmSettings::kMaxPhotonCount);
  s.initial_radius = float(p.FloatIn("initial_radius", 0, 0, std::numeric_limits<float>::max()));
  // A radius beyond the scene's size gathers every photon at every visible point (a render
  // that takes the square of the radius longer, and a blur of everything).
  const float scene_size = Length(scene.bounds().hi - scene.bounds().lo);
  if (s.initial_radius > 0 && std::isfinite(scene_size) && s.initial_radius > scene_size)
    throw ErrorAt(p.LocOf("initial_radius"),
                  "integrator 'sppm': initial_radius {} is larger than the whole scene (its bounds' diagonal, {:.4g}): "
                  "give about a pixel's footprint, or 0 for the automatic radius",
                  s.initial_radius, scene_size);
  // alpha = 1 would never shrink the radius (no convergence); 0 would keep no photon.
  s.alpha = float(p.Float("alpha", s.alpha));
  if (!(s.alpha > 0 && s.alpha < 1))
    throw ErrorAt(p.LocOf("alpha"), "integrator 'sppm': alpha must lie strictly between 0 and 1 (2/3 is usual), got {}",
                  s.alpha);
  return std::make_unique<SppmIntegrator>(scene, s);
}

}  // namespace

const IntegratorRegistry& IntegratorPlugins() {
  static const IntegratorRegistry registry(
      "integrator", {},
      {
          {"path",
           {{"max_depth", PropType::kInteger}, {"rr_depth", PropType::kInteger}, {"caustics", PropType::kBoolean}},
           [](const Properties& p, const Scene& scene) -> std::unique_ptr<Integrator> {
             const PathDepths d = ParsePathDepths(p);
             return std::make_unique<PathIntegrator>(scene, d.max_depth, d.rr_depth, p.Bool("caustics", false));
           }},
          {"direct",
           {{"shading_samples", PropType::kInteger},
            {"emitter_samples", PropType::kInteger},
            {"bsdf_samples", PropType::kInteger}},
           [](const Properties& p, const Scene& scene) -> std::unique_ptr<Integrator> {
             int shading = int(p.IntIn("shading_samples", 1, 0, 1 << 16));
             return std::make_unique<DirectIntegrator>(scene, int(p.IntIn("emitter_samples", shading, 0, 1 << 16)),
                                                       int(p.IntIn("bsdf_samples", shading, 0, 1 << 16)));
           }},
          {"ptracer",
           {{"max_depth", PropType::kInteger}, {"rr_depth", PropType::kInteger}},
           [](const Properties& p, const Scene& scene) -> std::unique_ptr<Integrator> {
             const PathDepths d = ParsePathDepths(p);
             return std::make_unique<LightTracerIntegrator>(scene, d.max_depth, d.rr_depth);
           }},
          {"whitted",
           {{"max_depth", PropType::kInteger},
            {"shadow_grid", PropType::kInteger},
            {"wavelength_sets", PropType::kInteger},
            {"bailout", PropType::kFloat},
            {"ambient", PropType::kSpectrum}},
           MakeWhitted},
          {"sppm",
           {{"max_depth", PropType::kInteger},
            {"rr_depth", PropType::kInteger},
            {"photon_count", PropType::kInteger},
            {"initial_radius", PropType::kFloat},
            {"alpha", PropType::kFloat}},
           MakeSppm},
          {"aov", {{"aovs", PropType::kString}, {"integrator", PropType::kObject}}, MakeAovIntegrator},
      });
  return registry;
}

std::unique_ptr<Integrator> BuildIntegrator(const ObjectNode* node, const Scene& scene) {
  if (!node) return std::make_unique<PathIntegrator>(scene, -1, 5);
  return IntegratorPlugins().Build(*node, scene);
}

}  // namespace objektiv
