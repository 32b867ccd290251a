// The block loop of the camera-path integrators: a pixel's camera rays made and traced to their
// first hits together, then each sample's path estimated by Li.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "base/rng.h"
#include "render/direct_lighting.h"
#include "render/integrator.h"

namespace objektiv {

namespace {
constexpr int kCameraBatch = 64;  // samples of one pixel whose camera rays are made together

// The samples of one batch; each keeps its sampler state so that its path goes on where the
// camera ray left off, and what it estimated until it is written.
struct CameraBatch {
  CameraBatch(const Sampler& prototype, int aov_channels)
      : samplers(kCameraBatch, prototype), filter_samples(kCameraBatch), weights(kCameraBatch),
        lambdas(kCameraBatch), lambdas_emitted(kCameraBatch), camera_samples(kCameraBatch), rays(kCameraBatch), first_rays(kCameraBatch),
        first_hits(kCameraBatch), L(kCameraBatch), Le(kCameraBatch),
        aovs(size_t(kCameraBatch) * std::max(aov_channels, 0)) {}
  std::vector<Sampler> samplers;
  std::vector<FilterSample> filter_samples;
  std::vector<float> weights;  // the filter's sample weight x the pattern's
  std::vector<SampledWavelengths> lambdas;
  std::vector<SampledWavelengths> lambdas_emitted;  // as they were before Li (which may drop some)
  std::vector<CameraSample> camera_samples;
  std::vector<std::optional<CameraRay>> rays;
  std::vector<const Ray*> first_rays;
  std::vector<std::optional<SurfaceInteraction>> first_hits;
  std::vector<SampledSpectrum> L, Le;
  std::vector<float> aovs;  // aov_channels per sample
};

// A sample of the whitted mode's lattice, kept until the pixel's tree is done.
struct LatticeSample {
  SampledSpectrum L, Le;
  SampledWavelengths lambda, lambda_emitted;
  float filter_weight = 0;
  bool has_ray = false;
  float Y = 0;
  double weight = 0;  // the sum of its leaves' shares of the pixel
  size_t aov = 0;     // its values' offset in the pixel's AOV store
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
  const int aov_channels = std::max(ctx.AovChannels(), 0);
  CameraBatch b(ctx.sampler(), aov_channels);

  // Starts sample k of the batch at (pixel, index): its film position (the sampler's pattern,
  // or `u_film` when given), its wavelengths (from `u_lambda` when given; the sampler's
  // dimension is taken either way) and its lens position.
  auto start = [&](int k, Vec2i pixel, int index, const Vec2f* u_film, const float* u_lambda) {
    Sampler& sk = b.samplers[k];
    sk.StartPixelSample(pixel, index);
    PatternSample ps = sk.GetPixelSample();
    if (u_film) ps = {*u_film, 1.f};
    b.filter_samples[k] = ctx.filter().Sample(ps.u);
    b.weights[k] = b.filter_samples[k].weight * ps.weight;
    const float ul = sk.Get1D();
    b.lambdas[k] = SampledWavelengths::SampleVisible(u_lambda ? *u_lambda : ul);
    const Vec2f offset = b.filter_samples[k].offset;
    const Vec2f lens = lens_sample ? sk.Get2D() : Vec2f(0.5f, 0.5f);
    b.camera_samples[k] = {Vec2f(pixel.x + 0.5f + offset.x, pixel.y + 0.5f + offset.y), lens, pixel};
  };
  // Traces the batch's n samples (started) and estimates each: b.L, b.Le, b.aovs.
  auto trace = [&](Vec2i pixel, int n) {
    camera.GenerateRays(std::span(b.camera_samples.data(), n), std::span(b.lambdas.data(), n),
                        std::span(b.rays.data(), n), ctx.camera_rays());
    for (int k = 0; k < n; ++k) {
      b.first_rays[k] = b.rays[k] ? &b.rays[k]->ray : nullptr;
      ctx.rays().closest += b.rays[k].has_value();
    }
    scene_.IntersectCoherent(std::span(b.first_rays.data(), n), std::span(b.first_hits.data(), n));
    for (int k = 0; k < n; ++k) {
      const std::optional<CameraRay>& cr = b.rays[k];
      b.L[k] = SampledSpectrum(0.f);
      // What the camera sees of emitters directly (before Li, which may drop wavelengths).
      if (cr && keep_emitted) {
        b.Le[k] = cr->weight * DirectEmission(cr->ray, b.first_hits[k], b.lambdas[k]);
        b.lambdas_emitted[k] = b.lambdas[k];
      }
      if (aov_channels > 0 && cr)
        EvaluateAovs(cr->ray, b.first_hits[k], b.lambdas[k],
                     Hash(pixel.x, pixel.y, b.samplers[k].index(), 0xa0), &b.aovs[size_t(k) * aov_channels]);
      if (cr) b.L[k] = cr->weight * Li(cr->ray, b.first_hits[k], b.lambdas[k], b.samplers[k], ctx);
      TraceLightPaths(b.samplers[k], ctx);
    }
  };
  // Writes an estimate with the given weight.
  auto write = [&](Vec2i pixel, const SampledSpectrum& L, const SampledWavelengths& lambda, const SampledSpectrum& Le,
                   const SampledWavelengths& lambda_emitted, bool has_ray, const float* aov, float weight) {
    if (has_ray && keep_emitted) ctx.AddEmitted(pixel, Le, lambda_emitted, weight);
    if (has_ray && aov_channels > 0) ctx.AddAovs(pixel, aov, weight);
    ctx.AddSample(pixel, L, lambda, weight);
  };

  if (ctx.sampler().adaptive().mode == AdaptiveMode::kWhitted) {
    const AdaptiveSettings& a = ctx.sampler().adaptive();
    const int cells = 1 << (a.max_depth + 1), side = cells + 1;  // lattice points per axis
    std::vector<int> at(size_t(side) * side, -1);                // lattice point -> its sample
    std::vector<LatticeSample> samples;
    std::vector<float> aov_store;
    struct Square {
      int x, y, size, depth;  // in lattice cells
    };
    std::vector<Square> level, next_level;
    std::vector<int> todo;
    ctx.ForEachWholePixel([&](Vec2i pixel) {
      std::fill(at.begin(), at.end(), -1);
      samples.clear();
      aov_store.clear();
      // One wavelength sample for the pixel: that of its sample 0.
      Sampler s0 = ctx.sampler();
      s0.StartPixelSample(pixel, 0);
      s0.GetPixelSample();
      const float u_lambda = s0.Get1D();
      auto points = [](const Square& q) {
        const int h = q.size / 2;
        return std::array<Vec2i, 5>{Vec2i(q.x + h, q.y + h), Vec2i(q.x, q.y), Vec2i(q.x + q.size, q.y),
                                    Vec2i(q.x, q.y + q.size), Vec2i(q.x + q.size, q.y + q.size)};
      };
      level.assign(1, Square{0, 0, cells, 0});
      while (!level.empty()) {
        // The level's new lattice points, traced in batches.
        todo.clear();
        for (const Square& q : level)
          for (Vec2i p : points(q)) {
            int& slot = at[size_t(p.y) * side + p.x];
            if (slot == -1) {
              slot = -2;
              todo.push_back(p.y * side + p.x);
            }
          }
        for (size_t t0 = 0; t0 < todo.size(); t0 += kCameraBatch) {
          const int n = int(std::min<size_t>(kCameraBatch, todo.size() - t0));
          for (int k = 0; k < n; ++k) {
            const int id = todo[t0 + k];
            const Vec2f u(std::min(float(id % side) / cells, kOneMinusEpsilon),
                          std::min(float(id / side) / cells, kOneMinusEpsilon));
            start(k, pixel, id, &u, &u_lambda);
          }
          trace(pixel, n);
          for (int k = 0; k < n; ++k) {
            LatticeSample ls{b.L[k], b.Le[k], b.lambdas[k], b.lambdas_emitted[k], b.weights[k], b.rays[k].has_value(),
                             SampledToXYZ(b.L[k], b.lambdas[k]).y, 0, aov_store.size()};
            aov_store.insert(aov_store.end(), b.aovs.begin() + size_t(k) * aov_channels,
                             b.aovs.begin() + size_t(k + 1) * aov_channels);
            at[todo[t0 + k]] = int(samples.size());
            samples.push_back(ls);
          }
        }
        // Each square: subdivided where its samples differ, else a leaf sharing out its area.
        next_level.clear();
        for (const Square& q : level) {
          const std::array<Vec2i, 5> p = points(q);
          float lo = INFINITY, hi = -INFINITY;
          for (Vec2i v : p) {
            const float Y = samples[at[size_t(v.y) * side + v.x]].Y;
            lo = std::min(lo, Y), hi = std::max(hi, Y);
          }
          const double contrast = (double(hi) - lo) / (double(hi) + lo + a.floor);
          if (q.depth < a.max_depth && !(contrast <= a.threshold)) {
            const int h = q.size / 2;
            for (int j = 0; j < 4; ++j) next_level.push_back({q.x + (j % 2) * h, q.y + (j / 2) * h, h, q.depth + 1});
            continue;
          }
          const double area = double(q.size) * q.size / (double(cells) * cells);
          for (int j = 0; j < 5; ++j) samples[at[size_t(p[j].y) * side + p[j].x]].weight += area * (j == 0 ? 0.5 : 0.125);
        }
        std::swap(level, next_level);
      }
      for (const LatticeSample& s : samples)
        write(pixel, s.L, s.lambda, s.Le, s.lambda_emitted, s.has_ray, aov_store.data() + s.aov, float(s.weight * s.filter_weight));
      return int(samples.size());
    });
    return;
  }

  ctx.ForEachPixel([&](Vec2i pixel, SampleRange samples) {
    for (int s0 = samples.begin; s0 < samples.end; s0 += kCameraBatch) {
      const int n = std::min(kCameraBatch, samples.end - s0);
      for (int k = 0; k < n; ++k) start(k, pixel, s0 + k, nullptr, nullptr);
      trace(pixel, n);
      for (int k = 0; k < n; ++k)
        write(pixel, b.L[k], b.lambdas[k], b.Le[k], b.lambdas_emitted[k], b.rays[k].has_value(),
              b.aovs.data() + size_t(k) * aov_channels,
              b.weights[k]);
    }
  });
}

}  // namespace objektiv
