// The film accumulates spectral radiance as CIE XYZ, per pixel of the crop window, in double
// so that sums of sample ranges merge exactly enough. Two estimates add up in each pixel:
// - camera samples of the pixel: sum of w * XYZ and sum of w (w the filter's sample weight;
//   the pixel reads their ratio, the filtered radiance);
// - splats: contributions at any film position (light paths reaching the sensor), spread over
//   the pixels by the normalised filter f(p - centre) / integral of f, so that a pixel measures
//   what its camera samples measure; the pixel reads their sum divided by the samples per
//   pixel rendered (pbrt-v4's light tracer normalisation).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "base/color_space.h"
#include "base/image.h"
#include "base/sampled_spectrum.h"
#include "render/filter.h"

namespace objektiv {

struct CropWindow {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // half-open pixel bounds on the full film
  int Width() const { return x1 - x0; }
  int Height() const { return y1 - y0; }
};

class Film {
  struct Pixel {
    double xyz[3] = {0, 0, 0};
    double weight = 0;
  };

 public:
  Film(int width, int height, CropWindow crop, std::shared_ptr<const Filter> filter);

  // A camera sample of a pixel in the crop window. Not synchronised: one thread writes a pixel
  // at a time (the renderer gives each pixel to one block).
  void AddSample(Vec2i pixel, const SampledSpectrum& L, const SampledWavelengths& lambda, float weight);
  // The part of a camera sample's radiance that came straight from an emitter (what the first
  // hit emits, or an environment seen directly), kept apart when asked for (KeepEmitted):
  // the light the stop's diffraction spreads (render/diffraction_glare.h). Given with the
  // sample's AddSample (same pixel, same weight), before or after it.
  void KeepEmitted() { emitted_xyz_.assign(3 * pixels_.size(), 0.0); }
  bool keeps_emitted() const { return !emitted_xyz_.empty(); }
  void AddEmitted(Vec2i pixel, const SampledSpectrum& Le, const SampledWavelengths& lambda, float weight);
  // Arbitrary output variables (render/aov.h): `channels` values per camera ray, averaged per
  // pixel with the samples' filter weights over the samples that start a ray (through a real
  // lens, many do not: they describe nothing). Not synchronised, as AddSample.
  void KeepAovs(int channels) {
    aov_channels_ = channels;
    aov_sums_.assign(size_t(channels) * pixels_.size(), 0.0);
    aov_weights_.assign(pixels_.size(), 0.0);
  }
  int aov_channels() const { return aov_channels_; }
  void AddAovs(Vec2i pixel, const float* values, float weight) {
    double* sum = &aov_sums_[size_t(aov_channels_) * Index(pixel)];
    for (int c = 0; c < aov_channels_; ++c) sum[c] += double(weight) * values[c];
    aov_weights_[Index(pixel)] += weight;
  }
  // Crop-window sized, interleaved, `aov_channels()` per pixel.
  std::vector<float> Aovs() const;
  // A contribution at a continuous film position (full-film pixel coordinates); the parts that
  // fall outside the crop window are dropped. Thread-safe: atomic adds in double. The sum of a
  // pixel's splats is exact up to double rounding, whose order is the order the threads happen
  // to deliver them: with one thread it is bit for bit reproducible; on any number of threads
  // it differs from that by double rounding only (relative 1e-16 per splat; in the float image
  // that rarely shows, and then by an ulp). Splats of exactly representable sums (such as
  // repeated equal contributions) are bit for bit the same on any thread count.
  void AddSplat(Vec2f p_film, const SampledSpectrum& L, const SampledWavelengths& lambda);
  // The renderer records every sample range it renders into the film (splats are divided by
  // the samples per pixel in all, so that ranges rendered one after another add up).
  void AddSamplesPerPixel(int n) { samples_per_pixel_ += n; }
  int64_t samples_per_pixel() const { return samples_per_pixel_; }
  // Linear RGB in the given colour space, scaled by 2^exposure; crop-window sized: the
  // filtered camera samples plus the splats.
  Image ToImage(const ColorSpace& cs, float exposure_stops = 0) const;
  // The film's XYZ (crop-window sized, interleaved): what ToImage shows before the colour space
  // and the exposure; and the emitted part alone (KeepEmitted), weighted as the pixel's samples.
  std::vector<float> Xyz() const;
  std::vector<float> EmittedXyz() const;

  // Bytes of the accumulators for a crop window (allocated by the constructor).
  static uint64_t AccumulatorBytes(const CropWindow& crop) {
    return uint64_t(crop.Width()) * crop.Height() * (sizeof(Pixel) + 3 * sizeof(double));  // samples and splats
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
  std::vector<double> splat_xyz_;  // 3 per pixel, added to through std::atomic_ref
  int aov_channels_ = 0;
  std::vector<double> aov_sums_, aov_weights_;
  std::vector<double> emitted_xyz_;  // 3 per pixel, weighted sums (like Pixel::xyz); empty unless kept
  int64_t samples_per_pixel_ = 0;
};

// Linear RGB in `cs`, scaled by 2^exposure, of an XYZ image (interleaved, width x height).
Image XyzToImage(const std::vector<float>& xyz, int width, int height, const ColorSpace& cs, float exposure_stops = 0);

// XYZ of a spectral sample (Monte Carlo estimate over the wavelength bundle).
Vec3f SampledToXYZ(const SampledSpectrum& L, const SampledWavelengths& lambda);

}  // namespace objektiv
