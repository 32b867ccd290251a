// The film accumulates spectral radiance as CIE XYZ, per pixel of the crop window, in exact
// sums (base/exact_sum.h) so that the sums of sample ranges rendered apart (a split render's
// parts, a render stopped and resumed) merge into the very sums of one render. Two estimates
// add up in each pixel:
// - camera samples of the pixel: sum of w * XYZ and sum of w (w the filter's sample weight;
//   the pixel reads their ratio, the filtered radiance);
// - splats: contributions at any film position (light paths reaching the sensor), spread over
//   the pixels by the normalised filter f(p - centre) / integral of f, so that a pixel measures
//   what its camera samples measure; the pixel reads their sum divided by the samples per
//   pixel rendered (pbrt-v4's light tracer normalisation).
// Each pixel also counts its samples (the renderer adds a pixel's count once all of its
// samples of a block are in), which says where a stopped render goes on, and keeps the sum of
// w * Y^2 for the noise estimate (render/noise_estimate.h).
#pragma once
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "base/color_space.h"
#include "base/exact_sum.h"
#include "base/image.h"
#include "base/sampled_spectrum.h"
#include "render/filter.h"

namespace objektiv {

struct CropWindow {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // half-open pixel bounds on the full film
  int Width() const { return x1 - x0; }
  int Height() const { return y1 - y0; }
  bool Contains(const CropWindow& o) const { return o.x0 >= x0 && o.y0 >= y0 && o.x1 <= x1 && o.y1 <= y1; }
  bool operator==(const CropWindow&) const = default;
};

// What a film has accumulated, as planes of exact sums (names: X, Y, Z, W (weights), YY,
// then emitted.X/Y/Z where kept, aov.0... and aov.W where kept, splat.X/Y/Z) and each pixel's
// sample count, crop-window sized: what a render part or a checkpoint stores
// (io/render_part.h), and what films of the same settings add up.
struct FilmAccumulators {
  CropWindow crop;
  std::vector<std::string> names;
  std::vector<ExactSum> sums;    // names.size() per pixel, pixel after pixel
  std::vector<uint32_t> counts;  // samples per pixel
  int first_sample = 0;          // the sample index the counts start from
};

class Film {
  struct Pixel {
    ExactSum xyz[3], weight, yy;  // sums of w * XYZ, w and w * Y^2
  };

 public:
  Film(int width, int height, CropWindow crop, std::shared_ptr<const Filter> filter);

  // A camera sample of a pixel in the crop window. Not synchronised: one thread writes a pixel
  // at a time (the renderer gives each pixel to one block).
  void AddSample(Vec2i pixel, const SampledSpectrum& L, const SampledWavelengths& lambda, float weight);
  // The same for an estimate already in XYZ (an integrator that sums its samples itself: sppm).
  void AddXyzSample(Vec2i pixel, const Vec3f& xyz, float weight);
  // The part of a camera sample's radiance that came straight from an emitter (what the first
  // hit emits, or an environment seen directly), kept apart when asked for (KeepEmitted):
  // the light the stop's diffraction spreads (render/diffraction_glare.h). Given with the
  // sample's AddSample (same pixel, same weight), before or after it.
  void KeepEmitted() { emitted_xyz_.assign(3 * pixels_.size(), ExactSum()); }
  bool keeps_emitted() const { return !emitted_xyz_.empty(); }
  void AddEmitted(Vec2i pixel, const SampledSpectrum& Le, const SampledWavelengths& lambda, float weight);
  void AddEmittedXyz(Vec2i pixel, const Vec3f& xyz, float weight);
  // Arbitrary output variables (render/aov.h): `channels` values per camera ray, averaged per
  // pixel with the samples' filter weights over the samples that start a ray (through a real
  // lens, many do not: they describe nothing). Not synchronised, as AddSample.
  void KeepAovs(int channels) {
    aov_channels_ = channels;
    aov_sums_.assign(size_t(channels) * pixels_.size(), ExactSum());
    aov_weights_.assign(pixels_.size(), ExactSum());
  }
  int aov_channels() const { return aov_channels_; }
  void AddAovs(Vec2i pixel, const float* values, float weight) {
    ExactSum* sum = &aov_sums_[size_t(aov_channels_) * Index(pixel)];
    for (int c = 0; c < aov_channels_; ++c) sum[c].Add(double(weight) * values[c]);
    aov_weights_[Index(pixel)].Add(weight);
  }
  // Crop-window sized, interleaved, `aov_channels()` per pixel.
  std::vector<float> Aovs() const;
  // A contribution at a continuous film position (full-film pixel coordinates); the parts that
  // fall outside the crop window are dropped. Thread-safe (a lock per stripe of pixels); the
  // sums are exact (base/exact_sum.h), so the order in which the threads deliver the splats
  // does not show: bit for bit the same image on any thread count.
  void AddSplat(Vec2f p_film, const SampledSpectrum& L, const SampledWavelengths& lambda);
  // Samples per pixel so far: the film's samples over its pixels (splats are divided by it, so
  // that ranges rendered one after another, or some pixels' samples only, add up).
  double samples_per_pixel() const;
  // The samples a pixel of the crop window has, and the index of its next one (from
  // StartSamplesAt's index on, 0 unless set): the renderer takes each pixel's samples from there.
  uint32_t SampleCount(Vec2i pixel) const { return counts_[Index(pixel)]; }
  int NextSample(Vec2i pixel) const { return first_sample_ + int(counts_[Index(pixel)]); }
  void AddSampleCount(Vec2i pixel, int n) { counts_[Index(pixel)] += uint32_t(n); }
  void StartSamplesAt(int index) { first_sample_ = index; }
  // Over the crop window: the samples of [begin, end) the pixels do not have yet, and the pixels
  // that have every sample up to `end`.
  int64_t SamplesLeft(int begin, int end) const;
  uint64_t PixelsWithSamplesTo(int end) const;
  int first_sample() const { return first_sample_; }
  // Per pixel of the crop window: sample count, mean luminance and the variance of a sample's
  // luminance (for the noise estimate); count 0 where no camera sample weighs in (a film of
  // splats only says nothing of its noise).
  struct LuminanceMoments {
    uint32_t count;
    double mean, variance;
  };
  LuminanceMoments Moments(size_t pixel_index) const;
  LuminanceMoments Moments(Vec2i pixel) const { return Moments(Index(pixel)); }
  size_t PixelCount() const { return pixels_.size(); }

  // What the film holds, and adding what another film of the same settings held (same planes,
  // a crop inside this film's crop: its pixels add to those). Throws std::invalid_argument
  // naming what does not match.
  FilmAccumulators Accumulators() const;
  // Those of a window of the crop (a strip at a time, for files).
  FilmAccumulators Accumulators(const CropWindow& window) const;
  std::vector<std::string> PlaneNames() const;
  void AddAccumulators(const FilmAccumulators& a);
  // Linear RGB in the given colour space, scaled by 2^exposure; crop-window sized: the
  // filtered camera samples plus the splats.
  Image ToImage(const ColorSpace& cs, float exposure_stops = 0) const;
  // The film's XYZ (crop-window sized, interleaved): what ToImage shows before the colour space
  // and the exposure; and the emitted part alone (KeepEmitted), weighted as the pixel's samples.
  std::vector<float> Xyz() const;
  std::vector<float> EmittedXyz() const;

  // Bytes of the accumulators for a crop window (allocated by the constructor).
  static uint64_t AccumulatorBytes(const CropWindow& crop) {
    return uint64_t(crop.Width()) * crop.Height() * (sizeof(Pixel) + 3 * sizeof(ExactSum) + sizeof(uint32_t));
  }

  int width() const { return width_; }
  int height() const { return height_; }
  const CropWindow& crop() const { return crop_; }
  const Filter& filter() const { return *filter_; }

 private:
  size_t Index(Vec2i p) const { return size_t(p.y - crop_.y0) * crop_.Width() + (p.x - crop_.x0); }
  int width_, height_;
  CropWindow crop_;
  std::shared_ptr<const Filter> filter_;
  float inv_filter_integral_;
  std::vector<Pixel> pixels_;
  std::vector<ExactSum> splat_xyz_;  // 3 per pixel, under splat_locks_
  std::unique_ptr<std::mutex[]> splat_locks_;
  std::vector<uint32_t> counts_;
  int first_sample_ = 0;
  int aov_channels_ = 0;
  std::vector<ExactSum> aov_sums_, aov_weights_;
  std::vector<ExactSum> emitted_xyz_;  // 3 per pixel, weighted sums (like Pixel::xyz); empty unless kept
};

// Linear RGB in `cs`, scaled by 2^exposure, of an XYZ image (interleaved, width x height).
Image XyzToImage(const std::vector<float>& xyz, int width, int height, const ColorSpace& cs, float exposure_stops = 0);

// XYZ of a spectral sample (Monte Carlo estimate over the wavelength bundle).
Vec3f SampledToXYZ(const SampledSpectrum& L, const SampledWavelengths& lambda);

}  // namespace objektiv
