// Spectral distributions as given in a scene: constants, RGB colours (as reflectance,
// unbounded value or illuminant), blackbodies, named illuminants and tabulated data.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "base/rgb_to_spectrum.h"

namespace objektiv {

class Spectrum {
 public:
  enum class Kind { kConstant, kRgbAlbedo, kRgbUnbounded, kRgbIlluminant, kBlackbody, kD65, kTabulated };

  Spectrum() : Spectrum(0.f) {}
  explicit Spectrum(float c) : kind_(Kind::kConstant), scale_(c) {}

  // Reflectance-like RGB in [0,1] (clamped).
  static Spectrum RgbAlbedo(Vec3f rgb);
  // Any non-negative RGB (e.g. a scattering coefficient): scale * sigmoid.
  static Spectrum RgbUnbounded(Vec3f rgb);
  // Emission: the unbounded RGB's spectrum times the luminance-normalised D65, so that
  // RGB (1,1,1) is D65 with Y = 1 and a camera looking at it records (1,1,1).
  static Spectrum RgbIlluminant(Vec3f rgb);
  // Planck's law at temperature T, normalised to a peak of 1, times scale.
  static Spectrum Blackbody(float temperature_k, float scale = 1);
  static Spectrum D65(float scale = 1);
  // Piecewise-linear through (lambda, value) pairs; constant beyond the ends.
  static Spectrum Tabulated(std::vector<float> lambdas, std::vector<float> values);

  float operator()(float lambda) const;
  SampledSpectrum Sample(const SampledWavelengths& w) const;
  Kind kind() const { return kind_; }
  bool IsConstant() const { return kind_ == Kind::kConstant; }
  float ConstantValue() const { return scale_; }
  // Upper bound over the visible range (for importance and clamping decisions).
  float MaxValue() const;
  Spectrum Scaled(float s) const;

 private:
  Kind kind_;
  float scale_ = 1;
  SigmoidPolynomial poly_;
  float temperature_ = 0, normalization_ = 1;
  std::shared_ptr<const std::vector<float>> lambdas_, values_;
};

// Luminance Y of a spectrum (for light-power estimates), integrated at 1 nm.
float SpectrumToY(const Spectrum& s);
// Linear RGB (Rec.709) of a spectrum seen as emission, for previews and tests.
Vec3f SpectrumToRgb(const Spectrum& s);

}  // namespace objektiv
