// The block loop of the camera-path integrators: a pixel's camera rays made and traced to their
// first hits together, then each sample's path estimated by Li (once per wavelength set).
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "base/rng.h"
#include "render/direct_lighting.h"
#include "render/integrator.h"

namespace objektiv {

namespace {
// Camera rays made together (samples x wavelength sets): of one pixel, or of several where
// each takes fewer samples than a batch holds (see the pixel loop at the end).
constexpr int kCameraBatch = 64;

// The slots of one batch, a camera sample's wavelength sets side by side (slot = sample x sets
// + set); each slot keeps its sampler state so that its path goes on where the camera ray left
// off, and what it estimated until it is written.
struct CameraBatch {
  CameraBatch(const Sampler& prototype, int aov_channels)
      : samplers(kCameraBatch, prototype), filter_samples(kCameraBatch), weights(kCameraBatch),
        lambdas(kCameraBatch), lambdas_emitted(kCameraBatch), camera_samples(kCameraBatch), pixels(kCameraBatch), rays(kCameraBatch),
        first_rays(kCameraBatch), first_hits(kCameraBatch), L(kCameraBatch), Le(kCameraBatch), xyz(kCameraBatch),
        xyz_emitted(kCameraBatch), aovs(size_t(kCameraBatch) * std::max(aov_channels, 0)) {}
  std::vector<Sampler> samplers;
  std::vector<FilterSample> filter_samples;
  std::vector<float> weights;  // the filter's sample weight x the pattern's
  std::vector<SampledWavelengths> lambdas;
  std::vector<SampledWavelengths> lambdas_emitted;  // as they were before Li (which may drop some)
  std::vector<CameraSample> camera_samples;
  std::vector<Vec2i> pixels;  // per sample (not slot): the pixel it belongs to
  std::vector<std::optional<CameraRay>> rays;
  std::vector<const Ray*> first_rays;
  std::vector<std::optional<SurfaceInteraction>> first_hits;
  std::vector<SampledSpectrum> L, Le;
  // Per sample (not slot): its sets' average in XYZ (empty: not finite), of what it saw straight from emitters.
  std::vector<std::optional<Vec3f>> xyz, xyz_emitted;
  std::vector<float> aovs;  // aov_channels per sample, at its set 0's wavelengths
};

// A sample of the whitted mode's lattice, kept until the pixel's tree is done.
struct LatticeSample {
  std::optional<Vec3f> xyz, xyz_emitted;
  float filter_weight = 0;
  bool has_ray = false;  // its set 0's camera ray
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
  const int sets = std::clamp(WavelengthSets(), 1, kMaxWavelengthSets);
  const int batch_samples = kCameraBatch / sets;
  CameraBatch b(ctx.sampler(), aov_channels);

  // Starts set `set` of a sample in slot j, at (pixel, index): its film position (the
  // sampler's pattern, or `u_film` when given), its wavelengths (from `u_lambda` when given;
  // the sampler's dimension is taken either way) and its lens position. Every set of a sample
  // starts its sampler alike.
  auto start = [&](int j, int set, Vec2i pixel, int index, const Vec2f* u_film, const float* u_lambda) {
    Sampler& sj = b.samplers[j];
    sj.StartPixelSample(pixel, index);
    PatternSample ps = sj.GetPixelSample();
    if (u_film) ps = {*u_film, 1.f};
    b.filter_samples[j] = ctx.filter().Sample(ps.u);
    b.weights[j] = b.filter_samples[j].weight * ps.weight;
    const float ul = sj.Get1D();
    // Set k's four at u + k / (4 sets) + i / 4; its first (the hero, which dispersive glass
    // keeps alone) turned to the (k mod 4)th of them, so that the sets' heroes spread over the
    // quarters of the range instead of sharing the first one (through dispersive glass four
    // sets were little better than two).
    float u = (u_lambda ? *u_lambda : ul) + float(set) / float(sets * kSpectrumSamples) +
              float(set % kSpectrumSamples) / float(kSpectrumSamples);
    u = std::min(u - std::floor(u), kOneMinusEpsilon);
    b.lambdas[j] = SampledWavelengths::SampleVisible(u);
    const Vec2f offset = b.filter_samples[j].offset;
    const Vec2f lens = lens_sample ? sj.Get2D() : Vec2f(0.5f, 0.5f);
    // Through a dispersive lens every wavelength of the sample is weighed with the filter below.
    b.camera_samples[j] = {Vec2f(pixel.x + 0.5f + offset.x, pixel.y + 0.5f + offset.y), lens, pixel, true};
    b.pixels[j / sets] = pixel;
  };
  // Traces the batch's n samples (started, n x sets slots) and estimates each: b.xyz,
  // b.xyz_emitted, b.aovs.
  auto trace = [&](int n) {
    const int slots = n * sets;
    camera.GenerateRays(std::span(b.camera_samples.data(), slots), std::span(b.lambdas.data(), slots),
                        std::span(b.rays.data(), slots), ctx.camera_rays());
    // Spectral MIS (camera/spectral_mis.h): each wavelength's film point weighed by the filter.
    for (int j = 0; j < slots; ++j)
      if (b.rays[j] && b.rays[j]->spectral)
        b.rays[j]->weight = SpectralMisWeight(*b.rays[j]->spectral, b.filter_samples[j].offset,
                                              [&](Vec2f p) { return ctx.filter().Evaluate(p); });
    // A set whose camera ray is its set 0's (a camera that does not depend on wavelength)
    // takes that ray's first hit.
    auto same_ray = [&](int j) {
      const int j0 = j - j % sets;
      return j != j0 && b.rays[j] && b.rays[j0] && b.rays[j]->ray.o == b.rays[j0]->ray.o &&
             b.rays[j]->ray.d == b.rays[j0]->ray.d && b.rays[j]->ray.tmax == b.rays[j0]->ray.tmax;
    };
    for (int j = 0; j < slots; ++j) {
      b.first_rays[j] = b.rays[j] && !same_ray(j) ? &b.rays[j]->ray : nullptr;
      ctx.rays().closest += b.first_rays[j] != nullptr;
    }
    scene_.IntersectCoherent(std::span(b.first_rays.data(), slots), std::span(b.first_hits.data(), slots));
    for (int j = 0; j < slots; ++j) {
      if (b.rays[j] && !b.first_rays[j]) b.first_hits[j] = b.first_hits[j - j % sets];  // (same_ray)
      const std::optional<CameraRay>& cr = b.rays[j];
      b.L[j] = SampledSpectrum(0.f);
      b.Le[j] = SampledSpectrum(0.f);
      b.lambdas_emitted[j] = b.lambdas[j];
      // What the camera sees of emitters directly (before Li, which may drop wavelengths).
      if (cr && keep_emitted) b.Le[j] = cr->weight * DirectEmission(cr->ray, b.first_hits[j], b.lambdas[j]);
      const int k = j / sets;
      if (aov_channels > 0 && cr && j % sets == 0)
        EvaluateAovs(cr->ray, b.first_hits[j], b.lambdas[j],
                     Hash(b.pixels[k].x, b.pixels[k].y, b.samplers[j].index(), 0xa0), &b.aovs[size_t(k) * aov_channels]);
      if (cr) b.L[j] = cr->weight * Li(cr->ray, b.first_hits[j], b.lambdas[j], b.samplers[j], ctx);
      if (j % sets == 0) TraceLightPaths(b.samplers[j], ctx);
    }
    for (int k = 0; k < n; ++k) {
      const size_t j0 = size_t(k) * sets;
      b.xyz[k] = ctx.SampleXyz(std::span(b.L.data() + j0, sets), std::span(b.lambdas.data() + j0, sets));
      b.xyz_emitted[k] = keep_emitted ? BlockContext::EmittedXyz(std::span(b.Le.data() + j0, sets),
                                                                   std::span(b.lambdas_emitted.data() + j0, sets))
                                      : std::nullopt;
    }
  };
  // Writes a sample's estimates with the given weight (`has_ray`: its set 0 made a camera ray,
  // at whose wavelengths its AOVs are).
  auto write = [&](Vec2i pixel, const std::optional<Vec3f>& xyz, const std::optional<Vec3f>& xyz_emitted, bool has_ray,
                   const float* aov, float weight) {
    if (xyz_emitted) ctx.AddEmitted(pixel, *xyz_emitted, weight);  // zero from a set without a camera ray
    if (has_ray && aov_channels > 0) ctx.AddAovs(pixel, aov, weight);
    if (xyz) ctx.AddSample(pixel, *xyz, weight);
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
        for (size_t t0 = 0; t0 < todo.size(); t0 += batch_samples) {
          const int n = int(std::min<size_t>(batch_samples, todo.size() - t0));
          for (int k = 0; k < n; ++k) {
            const int id = todo[t0 + k];
            const Vec2f u(std::min(float(id % side) / cells, kOneMinusEpsilon),
                          std::min(float(id / side) / cells, kOneMinusEpsilon));
            for (int set = 0; set < sets; ++set) start(k * sets + set, set, pixel, id, &u, &u_lambda);
          }
          trace(n);
          for (int k = 0; k < n; ++k) {
            const size_t j0 = size_t(k) * sets;
            LatticeSample ls{b.xyz[k], b.xyz_emitted[k], b.weights[j0], b.rays[j0].has_value(),
                             b.xyz[k] ? b.xyz[k]->y : 0.f, 0, aov_store.size()};
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
        write(pixel, s.xyz, s.xyz_emitted, s.has_ray, aov_store.data() + s.aov, float(s.weight * s.filter_weight));
      return int(samples.size());
    });
    return;
  }

  // Pixels that take fewer samples than a batch holds (a pass of one sample per pixel, a
  // preview) share batches: a lens traces a batch's rays side by side, and one ray alone
  // leaves most of its lanes idle (a preview through the double Gauss ran 3x slower so). The
  // samples are the same, their estimates written once their batch is traced: after their
  // pixel is counted (ForEachPixel), but within the block (the last batch after the loop,
  // also when the render stops), so the film still holds whole pixels. Statistical adaptive
  // sampling looks at a pixel's estimates between its batches: its pixels keep their own.
  const bool share = ctx.sampler().adaptive().mode == AdaptiveMode::kNone;
  int pending = 0;
  auto flush = [&] {
    if (pending == 0) return;
    trace(pending);
    for (int k = 0; k < pending; ++k)
      write(b.pixels[k], b.xyz[k], b.xyz_emitted[k], b.rays[size_t(k) * sets].has_value(),
            b.aovs.data() + size_t(k) * aov_channels, b.weights[size_t(k) * sets]);
    pending = 0;
  };
  ctx.ForEachPixel([&](Vec2i pixel, SampleRange samples) {
    for (int s = samples.begin; s < samples.end; ++s) {
      if (pending == batch_samples) flush();
      for (int set = 0; set < sets; ++set) start(pending * sets + set, set, pixel, s, nullptr, nullptr);
      ++pending;
    }
    if (!share) flush();
  });
  flush();
}

}  // namespace objektiv
