// The classic ray tracer (Whitted 1980, with the soft shadows of distributed ray tracing):
// light from every light source at each surface the camera sees, and the mirror reflections
// and refractions followed recursively. It answers quickly and nearly without noise, which is
// what a preview needs; what it leaves out is every other path of light (the light a diffuse
// surface passes on, caustics), as the classic tracers do.
//
// At a surface: its emission; for the BSDF's non-specular part (Lambert, Phong, plastic's and
// rough plastic's base and coat, blends' parts,
// rough metal and glass), the light of each light source, found by shadow rays: one for a
// point, spot or directional light (hard shadows), an n x n grid over an area or environment
// light, turned by one random offset per surface point (stratified and unbiased: soft shadows
// with little noise), and for glossy lobes as many samples of the BSDF, the two combined by
// multiple importance sampling; an optional ambient radiance times the diffuse reflectance; then each
// delta lobe (mirror, Fresnel-weighted reflection and refraction of smooth glass, total internal
// reflection included, plastic's coat) followed by a ray of its own, through the Beer-Lambert
// absorption of the glass it runs in; a glossy transmitter (rough glass) sends one ray sampled
// from its BSDF through, where the sample is a transmission (Cook's distributed ray tracing:
// what lies behind rough glass, blurred and, at one sample, grainy). Shadow rays stop at glass,
// as they do in the classic tracers and in the path tracer's light sampling: a light source
// behind a piece of rough glass is found from the glass's far side, where that ray leaves it.
//
// Each camera sample is estimated at wavelength_sets sets of wavelengths (default 4: sixteen
// wavelengths, CameraPathIntegrator::WavelengthSets), the sets' repeated rays answered by a
// RayMemo: a frame without the colour noise of four wavelengths a pixel, for less than the
// price of four frames (where glass disperses, the sets' rays part and each is traced).
//
// max_depth counts path segments as Mitsuba does (1: emitters seen directly, 2: direct
// light, each reflection or refraction one more), at most kMaxDepth: every branch is followed,
// so the recursion needs a bound (two mirrors facing each other never dim the light); a branch
// whose weight falls below `bailout` (POV-Ray's adc_bailout; at least kMinBailout, which keeps
// the branches of glass between mirrors few) is not followed.
#pragma once
#include <optional>

#include <tbb/enumerable_thread_specific.h>

#include "render/integrator.h"
#include "render/ray_memo.h"

namespace objektiv {

struct WhittedSettings {
  static constexpr int kMaxDepth = 64;
  static constexpr float kMinBailout = 1e-4f;
  int max_depth = 8;
  int shadow_grid = 4;  // n: n x n shadow rays per area or environment light
  int wavelength_sets = 4;
  float bailout = 1.f / 255;
  std::optional<Spectrum> ambient;  // radiance from every direction, unshadowed
};

class WhittedIntegrator final : public CameraPathIntegrator {
 public:
  WhittedIntegrator(const Scene& scene, WhittedSettings settings)
      : CameraPathIntegrator(scene), settings_(std::move(settings)) {}
  SampledSpectrum Li(const Ray& ray, const std::optional<SurfaceInteraction>& first_hit, SampledWavelengths& lambda,
                     Sampler& sampler, BlockContext& ctx) const override;
  bool LightsTheSceneItself() const override { return settings_.ambient.has_value(); }
  int WavelengthSets() const override { return settings_.wavelength_sets; }
  bool NearlyNoiseFree() const override { return true; }

 private:
  // Light leaving si toward the ray's origin (emission excluded); `weight` is the share of it
  // that reaches the camera, `segments` the path's segments so far.
  SampledSpectrum Shade(const SurfaceInteraction& si, SampledWavelengths& lambda, Sampler& sampler,
                        RayMemo& rays, const SampledSpectrum& weight, int segments) const;
  SampledSpectrum LightFromSources(const SurfaceInteraction& si, const BSDF& bsdf, const SampledWavelengths& lambda,
                                   Sampler& sampler, RayMemo& rays) const;
  // What lies behind a glossy transmitter (rough glass): one ray sampled from its BSDF, followed
  // where it is transmitted (the light sources seen through it are BsdfSamplesOfLight's).
  SampledSpectrum GlossyTransmission(const SurfaceInteraction& si, const BSDF& bsdf, SampledWavelengths& lambda,
                                     Sampler& sampler, RayMemo& rays, const SampledSpectrum& weight, int segments) const;
  // n x n samples of a glossy BSDF toward an area or environment light, weighted against the
  // light's own samples (multiple importance sampling, power heuristic).
  SampledSpectrum BsdfSamplesOfLight(const SurfaceInteraction& si, const BSDF& bsdf, const Light& light,
                                     const SampledWavelengths& lambda, Sampler& sampler, RayMemo& rays) const;
  WhittedSettings settings_;
  mutable tbb::enumerable_thread_specific<RayMemo> memos_;  // each thread's sample at a time
};

}  // namespace objektiv
