// The block loop of the camera-path integrators: a pixel's camera rays made and traced to their
// first hits together, then each sample's path estimated by Li.
#include <algorithm>
#include <vector>

#include "base/rng.h"
#include "render/direct_lighting.h"
#include "render/integrator.h"

namespace objektiv {

namespace {
constexpr int kCameraBatch = 64;  // samples of one pixel whose camera rays are made together

// The samples of one batch; each keeps its sampler state so that its path goes on where the
// camera ray left off.
struct CameraBatch {
  explicit CameraBatch(const Sampler& prototype)
      : samplers(kCameraBatch, prototype), filter_samples(kCameraBatch), lambdas(kCameraBatch),
        camera_samples(kCameraBatch), rays(kCameraBatch), first_rays(kCameraBatch), first_hits(kCameraBatch) {}
  std::vector<Sampler> samplers;
  std::vector<FilterSample> filter_samples;
  std::vector<SampledWavelengths> lambdas;
  std::vector<CameraSample> camera_samples;
  std::vector<std::optional<CameraRay>> rays;
  std::vector<const Ray*> first_rays;
  std::vector<std::optional<SurfaceInteraction>> first_hits;
};
}  // namespace

SampledSpectrum CameraPathIntegrator::DirectEmission(const Ray& ray, const std::optional<SurfaceInteraction>& hit,
                                                     const SampledWavelengths& lambda) const {
  SampledSpectrum Le(0.f);
  if (hit) return SegmentTransmittance(ray, *hit, lambda) * EmittedRadiance(*hit, lambda);
  for (const InfiniteLight* light : scene_.infinite_lights()) Le += light->Le(ray.d, lambda);
  return Le;
}

void CameraPathIntegrator::RenderBlock(BlockContext& ctx) const {
  const Camera& camera = ctx.camera();
  const bool lens_sample = camera.UsesLensSample();
  const bool keep_emitted = ctx.KeepsEmitted();
  const int aov_channels = ctx.AovChannels();
  std::vector<float> aov(size_t(std::max(aov_channels, 0)));
  CameraBatch b(ctx.sampler());
  ctx.ForEachPixel([&](Vec2i pixel, SampleRange samples) {
    for (int s0 = samples.begin; s0 < samples.end; s0 += kCameraBatch) {
      const int n = std::min(kCameraBatch, samples.end - s0);
      for (int k = 0; k < n; ++k) {
        Sampler& sk = b.samplers[k];
        sk.StartPixelSample(pixel, s0 + k);
        b.filter_samples[k] = ctx.filter().Sample(sk.GetPixel2D());
        b.lambdas[k] = SampledWavelengths::SampleVisible(sk.Get1D());
        Vec2f offset = b.filter_samples[k].offset;
        Vec2f lens = lens_sample ? sk.Get2D() : Vec2f(0.5f, 0.5f);
        b.camera_samples[k] = {Vec2f(pixel.x + 0.5f + offset.x, pixel.y + 0.5f + offset.y), lens, pixel};
      }
      camera.GenerateRays(std::span(b.camera_samples.data(), n), std::span(b.lambdas.data(), n),
                          std::span(b.rays.data(), n), ctx.camera_rays());
      for (int k = 0; k < n; ++k) {
        b.first_rays[k] = b.rays[k] ? &b.rays[k]->ray : nullptr;
        ctx.rays().closest += b.rays[k].has_value();
      }
      scene_.IntersectCoherent(std::span(b.first_rays.data(), n), std::span(b.first_hits.data(), n));
      for (int k = 0; k < n; ++k) {
        const std::optional<CameraRay>& cr = b.rays[k];
        SampledSpectrum L(0.f);
        // What the camera sees of emitters directly (before Li, which may drop wavelengths).
        if (cr && keep_emitted)
          ctx.AddEmitted(pixel, cr->weight * DirectEmission(cr->ray, b.first_hits[k], b.lambdas[k]), b.lambdas[k],
                         b.filter_samples[k].weight);
        if (aov_channels > 0 && cr) {
          EvaluateAovs(cr->ray, b.first_hits[k], b.lambdas[k], Hash(pixel.x, pixel.y, s0 + k, 0xa0), aov.data());
          ctx.AddAovs(pixel, aov.data(), b.filter_samples[k].weight);
        }
        if (cr) L = cr->weight * Li(cr->ray, b.first_hits[k], b.lambdas[k], b.samplers[k], ctx);
        ctx.AddSample(pixel, L, b.lambdas[k], b.filter_samples[k].weight);
        TraceLightPaths(b.samplers[k], ctx);
      }
    }
  });
}

}  // namespace objektiv
