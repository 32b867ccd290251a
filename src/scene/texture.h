// Textures: spectral values (reflectances, emission) or floats as functions of the surface point.
#pragma once
#include <memory>
#include <vector>

#include "base/image.h"
#include "base/sampled_spectrum.h"
#include "base/spectrum.h"
#include "base/transform.h"
#include "scene/interaction.h"

namespace objektiv {

// How an RGB from a texture becomes a spectrum. kData: the texture's numbers are data (a bump
// map's heights, a normal map's coordinates), read through Rgb and never made a spectrum;
// bitmaps for data are read without sRGB decoding unless the scene says otherwise.
enum class SpectrumUsage { kAlbedo, kUnbounded, kIlluminant, kData };

// Rec. 709 luminance of linear RGB: what a bump map reads as height from a colour texture.
inline float Luminance(const Vec3f& rgb) { return 0.2126f * rgb.x + 0.7152f * rgb.y + 0.0722f * rgb.z; }

class SpectrumTexture {
 public:
  virtual ~SpectrumTexture() = default;
  virtual SampledSpectrum Evaluate(Vec2f uv, const SampledWavelengths& lambda) const = 0;
  // Mean linear RGB over the texture (used for sampling weights, not for shading).
  virtual Vec3f MeanRgb() const = 0;
  // The value at uv as three plain numbers (linear RGB, or data such as a normal map's
  // coordinates), not as a spectrum.
  virtual Vec3f Rgb(Vec2f uv) const = 0;
  // The exact gradient (d/du, d/dv) of Luminance(Rgb) at uv wherever it is differentiable
  // (bilinear bitmaps: the slope of the bilinear patch; flat pieces: zero).
  virtual Vec2f LuminanceGradient(Vec2f uv) const = 0;
  // Whether the gradient is zero wherever it exists (a bump map made of it changes nothing).
  virtual bool IsPiecewiseConstant() const = 0;
};

// A spectrum that does not vary over the surface, tabulated at 1 nm over 360-830 nm when it
// is built (as pbrt's DenselySampledSpectrum), so that a lookup costs a linear interpolation
// instead of evaluating a sigmoid polynomial or an illuminant table per wavelength.
class ConstantTexture final : public SpectrumTexture {
 public:
  explicit ConstantTexture(Spectrum s);
  // `rgb`: the numbers the scene wrote (Rgb returns them exactly, for data).
  ConstantTexture(Spectrum s, Vec3f rgb);
  SampledSpectrum Evaluate(Vec2f, const SampledWavelengths& lambda) const override;
  Vec3f MeanRgb() const override;
  Vec3f Rgb(Vec2f) const override { return rgb_; }
  Vec2f LuminanceGradient(Vec2f) const override { return Vec2f(0, 0); }
  bool IsPiecewiseConstant() const override { return true; }

 private:
  Spectrum s_;
  Vec3f rgb_;
  std::vector<float> dense_;  // empty for constant spectra
};

// Mitsuba's checkerboard: color0 where floor(u*2)+floor(v*2) is even, color1 otherwise,
// after the to_uv transform.
class CheckerboardTexture final : public SpectrumTexture {
 public:
  // The mean is taken once here: the two colours may be one texture (a scene can nest such
  // checkerboards, and asking each for its mean on every call would take exponential time).
  CheckerboardTexture(std::shared_ptr<const SpectrumTexture> c0, std::shared_ptr<const SpectrumTexture> c1,
                      const Transform& to_uv)
      : c0_(std::move(c0)), c1_(std::move(c1)), to_uv_(to_uv), mean_((c0_->MeanRgb() + c1_->MeanRgb()) * 0.5f) {}
  SampledSpectrum Evaluate(Vec2f uv, const SampledWavelengths& lambda) const override;
  Vec3f MeanRgb() const override { return mean_; }
  Vec3f Rgb(Vec2f uv) const override { return Pick(uv).Rgb(uv); }
  // Inside a square, the gradient of its colour; the steps between squares have none.
  Vec2f LuminanceGradient(Vec2f uv) const override { return Pick(uv).LuminanceGradient(uv); }
  bool IsPiecewiseConstant() const override { return c0_->IsPiecewiseConstant() && c1_->IsPiecewiseConstant(); }

 private:
  const SpectrumTexture& Pick(Vec2f uv) const;
  std::shared_ptr<const SpectrumTexture> c0_, c1_;
  Transform to_uv_;
  Vec3f mean_;
};

enum class WrapMode { kRepeat, kMirror, kClamp };
enum class FilterMode { kBilinear, kNearest };

// A texel coordinate x (in texels, on an axis of n texels) brought into a range where its
// floor fits an int, without changing the texel it wraps to: moved by whole periods (n for
// repeat, 2n for mirror; exact, so the fraction is kept) or clamped to [-1, n]. NaN where
// there is no answer (x is NaN, or infinite and repeating); the caller then returns NaN.
float WrapTexelCoordinate(float x, WrapMode wrap, int n);

// An RGB image (linear, already decoded from sRGB by the loader) looked up at uv, v = 0 at
// the bottom row as in Mitsuba.
class BitmapTexture final : public SpectrumTexture {
 public:
  BitmapTexture(Image image, SpectrumUsage usage, FilterMode filter, WrapMode wrap, const Transform& to_uv);
  SampledSpectrum Evaluate(Vec2f uv, const SampledWavelengths& lambda) const override;
  Vec3f MeanRgb() const override { return mean_; }
  Vec3f LookupRgb(Vec2f uv) const;
  Vec3f Rgb(Vec2f uv) const override { return LookupRgb(uv); }
  Vec2f LuminanceGradient(Vec2f uv) const override;
  bool IsPiecewiseConstant() const override { return filter_ == FilterMode::kNearest; }
  // The texels as stored after decoding (linear values; what a lookup interpolates).
  const Image& image() const { return image_; }

 private:
  // The texel coordinates (x, y) of uv after to_uv and wrapping (NaN where there are none).
  Vec2f TexelCoordinates(Vec2f uv) const;
  Vec3f Texel(int x, int y) const;
  Image image_;
  SpectrumUsage usage_;
  FilterMode filter_;
  WrapMode wrap_;
  Transform to_uv_;
  Vec3f mean_;
};

SampledSpectrum RgbToSampled(Vec3f rgb, SpectrumUsage usage, const SampledWavelengths& lambda);

}  // namespace objektiv
