#include "render/film.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "base/cie.h"

namespace objektiv {

namespace {
constexpr size_t kSplatLocks = 1024;  // pixel i is under lock i % kSplatLocks
}  // namespace

Film::Film(int width, int height, CropWindow crop, std::shared_ptr<const Filter> filter)
    : width_(width), height_(height), crop_(crop), filter_(std::move(filter)),
      inv_filter_integral_(1 / filter_->Integral()), pixels_(size_t(crop.Width()) * crop.Height()),
      splat_xyz_(3 * pixels_.size()), splat_locks_(new std::mutex[kSplatLocks]), counts_(pixels_.size(), 0) {}

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
  AddXyzSample(pixel, SampledToXYZ(L, lambda), weight);
}

void Film::AddXyzSample(Vec2i pixel, const Vec3f& xyz, float weight) {
  Pixel& px = pixels_[Index(pixel)];
  for (int c = 0; c < 3; ++c) px.xyz[c].Add(double(weight) * xyz[c]);
  px.weight.Add(weight);
  px.yy.Add(double(weight) * (double(xyz[1]) * xyz[1]));  // a float squared is exact in double
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
      const size_t i = Index(Vec2i(x, y));
      ExactSum* sum = &splat_xyz_[3 * i];
      std::lock_guard lock(splat_locks_[i % kSplatLocks]);
      for (int c = 0; c < 3; ++c) sum[c].Add(double(w) * xyz[c]);
    }
}

void Film::AddEmitted(Vec2i pixel, const SampledSpectrum& Le, const SampledWavelengths& lambda, float weight) {
  if (emitted_xyz_.empty()) return;
  AddEmittedXyz(pixel, SampledToXYZ(Le, lambda), weight);
}

void Film::AddEmittedXyz(Vec2i pixel, const Vec3f& xyz, float weight) {
  if (emitted_xyz_.empty()) return;
  ExactSum* sum = &emitted_xyz_[3 * Index(pixel)];
  for (int c = 0; c < 3; ++c) sum[c].Add(double(weight) * xyz[c]);
}

double Film::samples_per_pixel() const {
  uint64_t total = 0;
  for (uint32_t n : counts_) total += n;
  if (counts_.empty()) return 0;
  // Whole numbers stay whole (a film whose pixels all have n samples divides its splats by n
  // exactly as n itself).
  if (total % counts_.size() == 0) return double(total / counts_.size());
  return double(total) / double(counts_.size());
}

int64_t Film::SamplesLeft(int begin, int end) const {
  int64_t left = 0;
  for (uint32_t n : counts_) left += std::max(0, end - std::max(begin, first_sample_ + int(n)));
  return left;
}

uint64_t Film::PixelsWithSamplesTo(int end) const {
  uint64_t done = 0;
  for (uint32_t n : counts_) done += first_sample_ + int(n) >= end;
  return done;
}

Film::LuminanceMoments Film::Moments(size_t i) const {
  const Pixel& px = pixels_[i];
  const double w = px.weight.Value();
  if (w == 0) return {0, 0, 0};  // no camera sample weighs in (splats only): nothing to estimate from
  const double mean = px.xyz[1].Value() / w;
  return {counts_[i], mean, std::max(0.0, px.yy.Value() / w - mean * mean)};
}

// The planes in their order: the pixel's sums, then the optional ones, then the splats.
std::vector<std::string> Film::PlaneNames() const {
  std::vector<std::string> names = {"X", "Y", "Z", "W", "YY"};
  if (keeps_emitted()) names.insert(names.end(), {"emitted.X", "emitted.Y", "emitted.Z"});
  for (int c = 0; c < aov_channels_; ++c) names.push_back(fmt::format("aov.{}", c));
  if (aov_channels_ > 0) names.push_back("aov.W");
  names.insert(names.end(), {"splat.X", "splat.Y", "splat.Z"});
  return names;
}

FilmAccumulators Film::Accumulators() const { return Accumulators(crop_); }

FilmAccumulators Film::Accumulators(const CropWindow& window) const {
  if (!crop_.Contains(window)) throw std::invalid_argument("Film::Accumulators: a window outside the crop");
  FilmAccumulators a;
  a.crop = window;
  a.first_sample = first_sample_;
  a.names = PlaneNames();
  const size_t n = a.names.size();
  a.sums.reserve(n * size_t(window.Width()) * window.Height());
  a.counts.reserve(size_t(window.Width()) * window.Height());
  for (int y = window.y0; y < window.y1; ++y)
    for (int x = window.x0; x < window.x1; ++x) {
      const size_t i = Index(Vec2i(x, y));
      const Pixel& px = pixels_[i];
      a.counts.push_back(counts_[i]);
      a.sums.insert(a.sums.end(), {px.xyz[0], px.xyz[1], px.xyz[2], px.weight, px.yy});
      if (keeps_emitted()) a.sums.insert(a.sums.end(), emitted_xyz_.data() + 3 * i, emitted_xyz_.data() + 3 * i + 3);
      const ExactSum* aov = aov_sums_.data() + size_t(aov_channels_) * i;
      a.sums.insert(a.sums.end(), aov, aov + aov_channels_);
      if (aov_channels_ > 0) a.sums.push_back(aov_weights_[i]);
      a.sums.insert(a.sums.end(), splat_xyz_.data() + 3 * i, splat_xyz_.data() + 3 * i + 3);
    }
  return a;
}

void Film::AddAccumulators(const FilmAccumulators& a) {
  const std::vector<std::string> names = PlaneNames();
  if (a.names != names)
    throw std::invalid_argument(fmt::format("its planes ({}) are not this render's ({})", fmt::join(a.names, ", "),
                                            fmt::join(names, ", ")));
  if (!crop_.Contains(a.crop))
    throw std::invalid_argument(fmt::format("its crop {},{},{},{} is not inside this render's {},{},{},{}", a.crop.x0,
                                            a.crop.y0, a.crop.x1, a.crop.y1, crop_.x0, crop_.y0, crop_.x1, crop_.y1));
  const size_t n = names.size(), pixels = size_t(a.crop.Width()) * a.crop.Height();
  if (a.sums.size() != n * pixels || a.counts.size() != pixels)
    throw std::invalid_argument("its planes do not have one value per pixel of its crop");
  for (int y = a.crop.y0; y < a.crop.y1; ++y)
    for (int x = a.crop.x0; x < a.crop.x1; ++x) {
      const size_t j = size_t(y - a.crop.y0) * a.crop.Width() + (x - a.crop.x0), i = Index(Vec2i(x, y));
      const ExactSum* in = &a.sums[n * j];
      Pixel& px = pixels_[i];
      for (int c = 0; c < 3; ++c) px.xyz[c].Add(*in++);
      px.weight.Add(*in++);
      px.yy.Add(*in++);
      if (keeps_emitted())
        for (int c = 0; c < 3; ++c) emitted_xyz_[3 * i + c].Add(*in++);
      for (int c = 0; c < aov_channels_; ++c) aov_sums_[size_t(aov_channels_) * i + c].Add(*in++);
      if (aov_channels_ > 0) aov_weights_[i].Add(*in++);
      for (int c = 0; c < 3; ++c) splat_xyz_[3 * i + c].Add(*in++);
      counts_[i] += a.counts[j];
    }
}

std::vector<float> Film::Xyz() const {
  std::vector<float> out(3 * pixels_.size());
  const double spp = samples_per_pixel();
  for (size_t i = 0; i < pixels_.size(); ++i) {
    const Pixel& px = pixels_[i];
    const ExactSum* splat = &splat_xyz_[3 * i];
    const double weight = px.weight.Value();
    for (int c = 0; c < 3; ++c) {
      double v = weight != 0 ? px.xyz[c].Value() / weight : 0;
      // (Only where splats landed: adding zero would turn a -0 into +0.)
      if (!splat[c].IsZero() && spp > 0) v += splat[c].Value() / spp;
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
      if (pixels_[i].weight.Value() != 0)
        out[3 * i + c] = float(emitted_xyz_[3 * i + c].Value() / pixels_[i].weight.Value());
  return out;
}

std::vector<float> Film::Aovs() const {
  const size_t n = size_t(aov_channels_);
  std::vector<float> out(n * pixels_.size(), 0.f);
  if (n == 0) return out;
  for (size_t i = 0; i < pixels_.size(); ++i)
    if (const double w = aov_weights_[i].Value(); w != 0)
      for (size_t c = 0; c < n; ++c) out[i * n + c] = float(aov_sums_[i * n + c].Value() / w);
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
