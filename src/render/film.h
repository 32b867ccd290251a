// The film accumulates spectral radiance as CIE XYZ, per pixel of the crop window:
// sum of w * XYZ and sum of w, in double so that sums of sample ranges merge exactly enough.
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

  void AddSample(Vec2i pixel, const SampledSpectrum& L, const SampledWavelengths& lambda, float weight);
  // Linear RGB in the given colour space, scaled by 2^exposure; crop-window sized.
  Image ToImage(const ColorSpace& cs, float exposure_stops = 0) const;

  // Bytes of the accumulators for a crop window (allocated by the constructor).
  static uint64_t AccumulatorBytes(const CropWindow& crop) { return uint64_t(crop.Width()) * crop.Height() * sizeof(Pixel); }

  int width() const { return width_; }
  int height() const { return height_; }
  const CropWindow& crop() const { return crop_; }
  const Filter& filter() const { return *filter_; }

 private:
  Pixel& At(Vec2i p) { return pixels_[size_t(p.y - crop_.y0) * crop_.Width() + (p.x - crop_.x0)]; }
  int width_, height_;
  CropWindow crop_;
  std::shared_ptr<const Filter> filter_;
  std::vector<Pixel> pixels_;
};

// XYZ of a spectral sample (Monte Carlo estimate over the wavelength bundle).
Vec3f SampledToXYZ(const SampledSpectrum& L, const SampledWavelengths& lambda);

}  // namespace objektiv
