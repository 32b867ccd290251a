// Integrators estimate the radiance arriving along a camera ray.
#pragma once
#include <cstdint>

#include "render/sampler.h"
#include "scene/scene.h"

namespace objektiv {

struct RayCounts {
  uint64_t closest = 0, shadow = 0;
};

class Integrator {
 public:
  explicit Integrator(const Scene& scene) : scene_(scene) {}
  virtual ~Integrator() = default;
  // Radiance along a camera ray whose first intersection the caller has already found (the
  // renderer traces a pixel's camera rays together, Scene::IntersectCoherent; empty: a miss).
  virtual SampledSpectrum Li(const Ray& ray, const std::optional<SurfaceInteraction>& first_hit,
                             SampledWavelengths& lambda, Sampler& sampler, RayCounts& counts) const = 0;
  const Scene& scene() const { return scene_; }

 protected:
  const Scene& scene_;
};

// Unidirectional path tracing with next-event estimation and multiple importance sampling.
// max_depth counts path segments as Mitsuba does (1: emitters seen directly, 2: direct
// lighting, -1: unbounded); Russian roulette from rr_depth on.
class PathIntegrator final : public Integrator {
 public:
  PathIntegrator(const Scene& scene, int max_depth, int rr_depth)
      : Integrator(scene), max_depth_(max_depth), rr_depth_(rr_depth) {}
  SampledSpectrum Li(const Ray& ray, const std::optional<SurfaceInteraction>& first_hit, SampledWavelengths& lambda,
                     Sampler& sampler, RayCounts& counts) const override;

 private:
  int max_depth_, rr_depth_;
};

// Direct illumination only: emitter and BSDF samples combined with the power heuristic
// (Mitsuba's `direct`).
class DirectIntegrator final : public Integrator {
 public:
  DirectIntegrator(const Scene& scene, int emitter_samples, int bsdf_samples)
      : Integrator(scene), emitter_samples_(emitter_samples), bsdf_samples_(bsdf_samples) {}
  SampledSpectrum Li(const Ray& ray, const std::optional<SurfaceInteraction>& first_hit, SampledWavelengths& lambda,
                     Sampler& sampler, RayCounts& counts) const override;

 private:
  int emitter_samples_, bsdf_samples_;
};

}  // namespace objektiv
