#include "render/film.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "base/cie.h"

namespace objektiv {

Film::Film(int width, int height, CropWindow crop, std::shared_ptr<const Filter> filter)
    : width_(width), height_(height), crop_(crop), filter_(std::move(filter)),
      inv_filter_integral_(1 / filter_->Integral()), pixels_(size_t(crop.Width()) * crop.Height()),
      splat_xyz_(3 * pixels_.size(), 0.0) {}

Vec3f SampledToXYZ(const SampledSpectrum& L, const SampledWavelengths& lambda) {
  Vec3f xyz(0.f);
  for (int i = 0; i < kSpectrumSamples; ++i) {
    float pdf = lambda.Pdf(i);
    if (pdf == 0) continue;
    xyz += CieXyz(lambda[i]) * (L[i] / pdf);
  }
  return xyz / (float(kSpectrumSamples) * CieYIntegral());
}

void Film::AddSample(Vec2i pixel, const SampledSpectrum& L, const SampledWavelengths& lambda, float weight) {
  Vec3f xyz = SampledToXYZ(L, lambda);
  Pixel& px = pixels_[Index(pixel)];
  for (int c = 0; c < 3; ++c) px.xyz[c] += double(weight) * xyz[c];
  px.weight += weight;
}

void Film::AddSplat(Vec2f p_film, const SampledSpectrum& L, const SampledWavelengths& lambda) {
  Vec3f xyz = SampledToXYZ(L, lambda);
  if (xyz == Vec3f(0.f)) return;
  // Pixels whose centre (x + 0.5, y + 0.5) lies within the filter's radius of p_film (none if
  // p_film is far outside the crop window or not finite).
  const float r = filter_->Radius();
  if (!(p_film.x > crop_.x0 - r - 1 && p_film.x < crop_.x1 + r + 1 && p_film.y > crop_.y0 - r - 1 &&
        p_film.y < crop_.y1 + r + 1))
    return;
  const int x0 = std::max(crop_.x0, int(std::ceil(p_film.x - 0.5f - r)));
  const int x1 = std::min(crop_.x1 - 1, int(std::floor(p_film.x - 0.5f + r)));
  const int y0 = std::max(crop_.y0, int(std::ceil(p_film.y - 0.5f - r)));
  const int y1 = std::min(crop_.y1 - 1, int(std::floor(p_film.y - 0.5f + r)));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      float w = filter_->Evaluate(Vec2f(p_film.x - (x + 0.5f), p_film.y - (y + 0.5f))) * inv_filter_integral_;
      if (w == 0) continue;
      double* sum = &splat_xyz_[3 * Index(Vec2i(x, y))];
      for (int c = 0; c < 3; ++c) std::atomic_ref<double>(sum[c]).fetch_add(double(w) * xyz[c], std::memory_order_relaxed);
    }
}

void Film::AddEmitted(Vec2i pixel, const SampledSpectrum& Le, const SampledWavelengths& lambda, float weight) {
  if (emitted_xyz_.empty()) return;
  const Vec3f xyz = SampledToXYZ(Le, lambda);
  double* sum = &emitted_xyz_[3 * Index(pixel)];
  for (int c = 0; c < 3; ++c) sum[c] += double(weight) * xyz[c];
}

std::vector<float> Film::Xyz() const {
  std::vector<float> out(3 * pixels_.size());
  for (size_t i = 0; i < pixels_.size(); ++i) {
    const Pixel& px = pixels_[i];
    const double* splat = &splat_xyz_[3 * i];
    for (int c = 0; c < 3; ++c) {
      double v = px.weight != 0 ? px.xyz[c] / px.weight : 0;
      // (Only where splats landed: adding zero would turn a -0 into +0.)
      if (splat[c] != 0 && samples_per_pixel_ > 0) v += splat[c] / double(samples_per_pixel_);
      out[3 * i + c] = float(v);
    }
  }
  return out;
}

std::vector<float> Film::EmittedXyz() const {
  std::vector<float> out(3 * pixels_.size(), 0.f);
  if (emitted_xyz_.empty()) return out;
  for (size_t i = 0; i < pixels_.size(); ++i)
    for (int c = 0; c < 3; ++c)
      if (pixels_[i].weight != 0) out[3 * i + c] = float(emitted_xyz_[3 * i + c] / pixels_[i].weight);
  return out;
}

std::vector<float> Film::Aovs() const {
  const size_t n = size_t(aov_channels_);
  std::vector<float> out(n * pixels_.size(), 0.f);
  if (n == 0) return out;
  for (size_t i = 0; i < pixels_.size(); ++i)
    if (aov_weights_[i] != 0)
      for (size_t c = 0; c < n; ++c) out[i * n + c] = float(aov_sums_[i * n + c] / aov_weights_[i]);
  return out;
}

Image Film::ToImage(const ColorSpace& cs, float exposure_stops) const {
  return XyzToImage(Xyz(), crop_.Width(), crop_.Height(), cs, exposure_stops);
}

Image XyzToImage(const std::vector<float>& xyz, int width, int height, const ColorSpace& cs, float exposure_stops) {
  Image img(width, height, {"R", "G", "B"});
  const float scale = std::exp2(exposure_stops);
  for (size_t i = 0; i < size_t(width) * height; ++i) {
    const Vec3f rgb = cs.ToRGB(Vec3f(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2])) * scale;
    for (int c = 0; c < 3; ++c) img.pixels[3 * i + c] = rgb[c];
  }
  return img;
}

}  // namespace objektiv
