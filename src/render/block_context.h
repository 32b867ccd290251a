// The contract between the render loop and an integrator. The renderer splits the crop window
// into blocks (a tile of pixels and a range of sample indices) and hands each to the integrator
// with a BlockContext: the camera, the sampler to copy, the film writes and this thread's
// counters. The integrator makes and traces its own rays. The renderer keeps what is common to
// all: the schedule, progress, the stop flag (ForEachPixel), statistics and NaN/Inf counting
// (AddSample, AddSplat), so that no integrator repeats them.
//
// Determinism: every random number must come from a copy of sampler() started at a (pixel,
// sample index) of the block (Sampler::StartPixelSample); nothing may depend on which thread
// runs a block or on the order of blocks. Film writes:
// - AddSample: a camera sample of a pixel of this block (only this block writes that pixel:
//   no synchronisation, and the pixel's sums are made in sample order, bit for bit the same on
//   any thread count and tiling).
// - AddSplat: a contribution at any film position (a light path reaching the sensor), from any
//   block at any time (atomic adds; see Film::AddSplat for what is guaranteed).
#pragma once
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>

#include "camera/camera.h"
#include "render/adaptive_sampling.h"
#include "render/film.h"
#include "render/sampler.h"

namespace objektiv {

struct RayCounts {
  uint64_t closest = 0, shadow = 0;
};

// One thread's statistics, summed by the renderer at the end.
struct RenderCounters {
  RayCounts rays;
  CameraRayCount camera;
  uint64_t nan = 0, inf = 0;  // radiance samples and splats dropped
  uint64_t samples = 0;       // pixel samples taken
  uint64_t whole_pixels = 0;  // pixels taken whole (AdaptiveMode::kWhitted: progress counts these)
};

// A tile of pixels (half-open bounds on the full film, inside the crop window) and the sample
// indices [sample_begin, sample_end) to take for each of its pixels: those it does not have yet
// (a pixel of a render stopped and resumed may have them all; see BlockContext::ForEachPixel).
struct PixelBlock {
  Vec2i p0, p1;
  int sample_begin = 0, sample_end = 0;
};

// The sample indices [begin, end) a pixel takes in its block.
struct SampleRange {
  int begin = 0, end = 0;
  int size() const { return end - begin; }
};

class BlockContext {
 public:
  BlockContext(const PixelBlock& block, const Camera& camera, const Sampler& sampler, Film& film,
               RenderCounters& counters, const std::atomic<bool>* stop)
      : block_(block), camera_(camera), sampler_(sampler), film_(film), counters_(counters), stop_(stop) {}

  const PixelBlock& block() const { return block_; }
  const Camera& camera() const { return camera_; }
  // The render's sampler, to be copied (one copy per sample in flight) and started per sample.
  const Sampler& sampler() const { return sampler_; }
  // The film's reconstruction filter: camera samples are placed by Filter::Sample.
  const Filter& filter() const { return film_.filter(); }

  // The pixel loop of every integrator: fn(pixel, samples) for the block's pixels in scanline
  // order, `samples` the block's sample indices that the pixel does not have yet (the film
  // counts each pixel's samples: a resumed render skips what it has), to be taken in full.
  // Once the render is stopped (Ctrl-C, a checkpoint, a time limit) no pixel is started any
  // more; a pixel's samples are counted once its fn returns, so a stopped film holds whole
  // pixels only and goes on from there.
  //
  // With statistical adaptive sampling (render/adaptive_sampling.h) fn is called for a pixel
  // once per batch, up to the rule's next look, until the rule says the pixel is done or the
  // block's samples end; each batch is in the film (and counted) before the rule looks.
  template <class PixelFn>
  void ForEachPixel(PixelFn&& fn) {
    const bool adaptive = sampler_.adaptive().mode == AdaptiveMode::kStatistical;
    for (int y = block_.p0.y; y < block_.p1.y; ++y)
      for (int x = block_.p0.x; x < block_.p1.x; ++x) {
        if (Stopped()) return;
        const Vec2i pixel(x, y);
        if (adaptive) {
          int next = std::max(block_.sample_begin, film_.NextSample(pixel));
          while (next < block_.sample_end && !PixelSamplingDone(film_, pixel, sampler_, sampler_.spp())) {
            const SampleRange batch{next, std::min(block_.sample_end, NextAdaptiveCheck(sampler_.adaptive(), next))};
            fn(pixel, batch);
            film_.AddSampleCount(pixel, batch.size());
            counters_.samples += uint64_t(batch.size());
            next = batch.end;
          }
          continue;
        }
        const SampleRange samples{std::max(block_.sample_begin, film_.NextSample(pixel)), block_.sample_end};
        if (samples.size() <= 0) continue;
        fn(pixel, samples);
        film_.AddSampleCount(pixel, samples.size());
        counters_.samples += uint64_t(samples.size());
      }
  }
  // The pixel loop of whole-pixel adaptive sampling (AdaptiveMode::kWhitted): fn(pixel) takes
  // all of a pixel's samples at once and returns how many; a pixel that has any is done.
  template <class PixelFn>
  void ForEachWholePixel(PixelFn&& fn) {
    for (int y = block_.p0.y; y < block_.p1.y; ++y)
      for (int x = block_.p0.x; x < block_.p1.x; ++x) {
        if (Stopped()) return;
        const Vec2i pixel(x, y);
        if (film_.SampleCount(pixel) > 0 || block_.sample_end <= 0) continue;
        const int n = fn(pixel);
        film_.AddSampleCount(pixel, n);
        counters_.samples += uint64_t(n);
        ++counters_.whole_pixels;
      }
  }
  bool Stopped() const { return stop_ && stop_->load(std::memory_order_relaxed); }
  // A path whose throughput went non-finite (ended, and counted as a NaN sample).
  void CountNaN() { ++counters_.nan; }

  // A camera sample's radiance at one or more sets of wavelengths as XYZ, the sets' average;
  // empty (and counted) if any is not finite.
  std::optional<Vec3f> SampleXyz(std::span<const SampledSpectrum> L, std::span<const SampledWavelengths> lambda) {
    return AverageXyz(L, lambda, [&](const SampledSpectrum& s) { return Finite(s); });
  }
  // One camera sample of a pixel of this block (SampleXyz), weighted by the filter's sample weight.
  void AddSample(Vec2i pixel, const Vec3f& xyz, float filter_weight) { film_.AddXyzSample(pixel, xyz, filter_weight); }
  // The part of a camera sample that came straight from an emitter, when the film keeps it
  // apart (Film::KeepEmitted): as SampleXyz, empty if any is not finite (not counted: the
  // sample's radiance is).
  bool KeepsEmitted() const { return film_.keeps_emitted(); }
  static std::optional<Vec3f> EmittedXyz(std::span<const SampledSpectrum> Le, std::span<const SampledWavelengths> lambda) {
    return AverageXyz(Le, lambda, [](const SampledSpectrum& s) { return !s.HasNaN() && !s.HasInf(); });
  }
  void AddEmitted(Vec2i pixel, const Vec3f& xyz, float filter_weight) { film_.AddEmittedXyz(pixel, xyz, filter_weight); }
  // The AOVs of a camera sample of a pixel of this block (the film's channels: Film::KeepAovs).
  int AovChannels() const { return film_.aov_channels(); }
  void AddAovs(Vec2i pixel, const float* values, float filter_weight) { film_.AddAovs(pixel, values, filter_weight); }
  // A contribution at a continuous film position (full-film pixel coordinates, as
  // CameraSample::p_film), spread over the pixels by the filter. The image shows the sum of a
  // pixel's splats divided by the samples per pixel of the render: an integrator that traces
  // one light path per (pixel, sample index) splats what that path brings to the sensor.
  void AddSplat(Vec2f p_film, const SampledSpectrum& L, const SampledWavelengths& lambda) {
    if (!std::isfinite(p_film.x) || !std::isfinite(p_film.y)) {
      ++counters_.nan;  // a position gone wrong is a NaN sample too
      return;
    }
    if (Finite(L)) film_.AddSplat(p_film, L, lambda);
  }

  // The factor for the splats of light paths traced one per camera sample: the film divides
  // splats by its samples per pixel, which counts one path per sample of every pixel of the
  // full film; a crop window's samples trace fewer (the full film's pixels over the crop's).
  float LightPathScale() const {
    const CropWindow& c = film_.crop();
    return float(double(film_.width()) * film_.height() / (double(c.Width()) * c.Height()));
  }

  // Every ray traced is counted here (closest hits and shadow rays), camera rays through a lens
  // in camera_rays() (Camera::GenerateRays does that).
  RayCounts& rays() { return counters_.rays; }
  CameraRayCount& camera_rays() { return counters_.camera; }

 private:
  // The average in XYZ of spectra at their wavelengths; empty if `usable` refuses one.
  template <class Usable>
  static std::optional<Vec3f> AverageXyz(std::span<const SampledSpectrum> L, std::span<const SampledWavelengths> lambda,
                                         Usable&& usable) {
    Vec3f xyz(0.f);
    for (size_t k = 0; k < L.size(); ++k) {
      if (!usable(L[k])) return std::nullopt;
      xyz += SampledToXYZ(L[k], lambda[k]);
    }
    return xyz / float(L.size());
  }
  // Non-finite radiance is counted and dropped, never written to the film; so is radiance
  // beyond kLargestRadiance, which the film's conversion to XYZ (over a wavelength's density)
  // and its sums over samples would carry past single precision into Inf and NaN pixels.
  static constexpr float kLargestRadiance = 1e25f;
  bool Finite(const SampledSpectrum& L) {
    if (L.HasNaN()) {
      ++counters_.nan;
      return false;
    }
    float largest = 0;
    for (int i = 0; i < kSpectrumSamples; ++i) largest = std::max(largest, std::abs(L[i]));
    if (!(largest <= kLargestRadiance)) {  // Inf too
      ++counters_.inf;
      return false;
    }
    return true;
  }

  const PixelBlock& block_;
  const Camera& camera_;
  const Sampler& sampler_;
  Film& film_;
  RenderCounters& counters_;
  const std::atomic<bool>* stop_;
};

}  // namespace objektiv
