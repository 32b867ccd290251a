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

// How an RGB from a texture becomes a spectrum.
enum class SpectrumUsage { kAlbedo, kUnbounded, kIlluminant };

class SpectrumTexture {
 public:
  virtual ~SpectrumTexture() = default;
  virtual SampledSpectrum Evaluate(Vec2f uv, const SampledWavelengths& lambda) const = 0;
  // Mean linear RGB over the texture (used for sampling weights, not for shading).
  virtual Vec3f MeanRgb() const = 0;
};

// A spectrum that does not vary over the surface, tabulated at 1 nm over 360-830 nm when it
// is built (as pbrt's DenselySampledSpectrum), so that a lookup costs a linear interpolation
// instead of evaluating a sigmoid polynomial or an illuminant table per wavelength.
class ConstantTexture final : public SpectrumTexture {
 public:
  explicit ConstantTexture(Spectrum s);
  SampledSpectrum Evaluate(Vec2f, const SampledWavelengths& lambda) const override;
  Vec3f MeanRgb() const override;

 private:
  Spectrum s_;
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

 private:
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

 private:
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
