#include "scene/texture.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/cie.h"

namespace objektiv {

ConstantTexture::ConstantTexture(Spectrum s) : ConstantTexture(s, Vec3f(0.f)) { rgb_ = MeanRgb(); }

ConstantTexture::ConstantTexture(Spectrum s, Vec3f rgb) : s_(std::move(s)), rgb_(rgb) {
  if (s_.IsConstant()) return;
  dense_.resize(size_t(kLambdaMax - kLambdaMin) + 2);
  for (size_t i = 0; i < dense_.size(); ++i) dense_[i] = s_(kLambdaMin + float(i));
}

SampledSpectrum ConstantTexture::Evaluate(Vec2f, const SampledWavelengths& lambda) const {
  if (dense_.empty()) return SampledSpectrum(s_.ConstantValue());
  SampledSpectrum r;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    float x = Clamp(lambda[i] - kLambdaMin, 0, kLambdaMax - kLambdaMin);
    int k = int(x);
    float t = x - float(k);
    r[i] = dense_[k] + t * (dense_[k + 1] - dense_[k]);
  }
  return r;
}

Vec3f ConstantTexture::MeanRgb() const { return s_.IsConstant() ? Vec3f(s_.ConstantValue()) : SpectrumToRgb(s_); }

SampledSpectrum RgbToSampled(Vec3f rgb, SpectrumUsage usage, const SampledWavelengths& lambda) {
  switch (usage) {
    case SpectrumUsage::kAlbedo:
      return RgbToSigmoid(rgb).Sample(lambda);
    case SpectrumUsage::kUnbounded:
    case SpectrumUsage::kData:  // never shaded with; as unbounded if it were
      return Spectrum::RgbUnbounded(rgb).Sample(lambda);
    case SpectrumUsage::kIlluminant:
      return Spectrum::RgbIlluminant(rgb).Sample(lambda);
  }
  return {};
}

float WrapTexelCoordinate(float x, WrapMode wrap, int n) {
  switch (wrap) {
    case WrapMode::kRepeat:
      return std::fmod(x, float(n));
    case WrapMode::kMirror:
      return std::fmod(x, 2.f * float(n));
    case WrapMode::kClamp:
      return std::isnan(x) ? x : std::clamp(x, -1.f, float(n));
  }
  return x;
}

namespace {
// Whether floor(x) is odd, in floating point (x may lie far beyond an int's range).
bool FloorIsOdd(float x) {
  float r = std::fmod(std::floor(x), 2.f);  // -1, 0 or 1; NaN for NaN or infinite x
  return r == 1 || r == -1;
}
}  // namespace

const SpectrumTexture& CheckerboardTexture::Pick(Vec2f uv) const {
  Vec3f p = to_uv_.Point(Vec3f(uv.x, uv.y, 0));
  return FloorIsOdd(p.x * 2) == FloorIsOdd(p.y * 2) ? *c0_ : *c1_;
}

SampledSpectrum CheckerboardTexture::Evaluate(Vec2f uv, const SampledWavelengths& lambda) const {
  return Pick(uv).Evaluate(uv, lambda);
}

BitmapTexture::BitmapTexture(Image image, SpectrumUsage usage, FilterMode filter, WrapMode wrap, const Transform& to_uv)
    : image_(std::move(image)), usage_(usage), filter_(filter), wrap_(wrap), to_uv_(to_uv) {
  Vec3d sum(0.0);
  for (int y = 0; y < image_.height; ++y)
    for (int x = 0; x < image_.width; ++x) sum += Vec3d(image_.Rgb(x, y));
  mean_ = Vec3f(sum / double(std::max(1, image_.width * image_.height)));
}

Vec3f BitmapTexture::Texel(int x, int y) const {
  auto wrap = [&](int i, int n) {
    switch (wrap_) {
      case WrapMode::kRepeat:
        return ((i % n) + n) % n;
      case WrapMode::kClamp:
        return std::clamp(i, 0, n - 1);
      case WrapMode::kMirror: {
        int period = 2 * n, m = ((i % period) + period) % period;
        return m < n ? m : period - 1 - m;
      }
    }
    return 0;
  };
  return image_.Rgb(wrap(x, image_.width), wrap(y, image_.height));
}

Vec2f BitmapTexture::TexelCoordinates(Vec2f uv) const {
  Vec3f p = to_uv_.Point(Vec3f(uv.x, uv.y, 0));
  // Row 0 is the top of the image; v = 0 is its bottom.
  float x = p.x * image_.width, y = (1 - p.y) * image_.height;
  if (filter_ == FilterMode::kBilinear) {
    x -= 0.5f;
    y -= 0.5f;
  }
  return {WrapTexelCoordinate(x, wrap_, image_.width), WrapTexelCoordinate(y, wrap_, image_.height)};
}

Vec3f BitmapTexture::LookupRgb(Vec2f uv) const {
  auto [x, y] = TexelCoordinates(uv);
  if (std::isnan(x) || std::isnan(y)) return Vec3f(std::numeric_limits<float>::quiet_NaN());
  if (filter_ == FilterMode::kNearest) return Texel(int(std::floor(x)), int(std::floor(y)));
  int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  float dx = x - x0, dy = y - y0;
  return (Texel(x0, y0) * (1 - dx) + Texel(x0 + 1, y0) * dx) * (1 - dy) +
         (Texel(x0, y0 + 1) * (1 - dx) + Texel(x0 + 1, y0 + 1) * dx) * dy;
}

Vec2f BitmapTexture::LuminanceGradient(Vec2f uv) const {
  if (filter_ == FilterMode::kNearest) return Vec2f(0, 0);
  auto [x, y] = TexelCoordinates(uv);
  if (std::isnan(x) || std::isnan(y)) return Vec2f(std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::quiet_NaN());
  // The bilinear patch L = (1-dy)((1-dx) L00 + dx L10) + dy((1-dx) L01 + dx L11) differentiated
  // in texel units; wrapping only changes which texels are the corners (clamping past the
  // last texel centre makes two corners equal: a flat border, as the lookup).
  int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  float dx = x - x0, dy = y - y0;
  float l00 = Luminance(Texel(x0, y0)), l10 = Luminance(Texel(x0 + 1, y0));
  float l01 = Luminance(Texel(x0, y0 + 1)), l11 = Luminance(Texel(x0 + 1, y0 + 1));
  float dl_dx = (l10 - l00) * (1 - dy) + (l11 - l01) * dy;
  float dl_dy = (l01 - l00) * (1 - dx) + (l11 - l10) * dx;
  // Texel units from the texture's (s, t) = to_uv (u, v): x = s W, y = (1 - t) H; and
  // (s, t) from (u, v) through to_uv's linear part (its first two rows and columns).
  float dl_ds = dl_dx * float(image_.width), dl_dt = -dl_dy * float(image_.height);
  Vec3f d_du = to_uv_.Vector(Vec3f(1, 0, 0)), d_dv = to_uv_.Vector(Vec3f(0, 1, 0));  // (ds, dt) per du, dv
  return {dl_ds * d_du.x + dl_dt * d_du.y, dl_ds * d_dv.x + dl_dt * d_dv.y};
}

SampledSpectrum BitmapTexture::Evaluate(Vec2f uv, const SampledWavelengths& lambda) const {
  return RgbToSampled(LookupRgb(uv), usage_, lambda);
}

}  // namespace objektiv
