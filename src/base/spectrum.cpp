#include "base/spectrum.h"

#include <algorithm>
#include <cmath>

#include "base/cie.h"
#include "base/color_space.h"

namespace objektiv {

Spectrum Spectrum::RgbAlbedo(Vec3f rgb) {
  Spectrum s;
  s.kind_ = Kind::kRgbAlbedo;
  s.scale_ = 1;
  s.poly_ = RgbToSigmoid(rgb);
  return s;
}

Spectrum Spectrum::RgbUnbounded(Vec3f rgb) {
  rgb = Max(rgb, Vec3f(0.f));
  float m = MaxComponent(rgb);
  Spectrum s;
  s.kind_ = Kind::kRgbUnbounded;
  // Scale so the sigmoid is fitted at half brightness: it leaves room on both sides.
  s.scale_ = 2 * m;
  s.poly_ = RgbToSigmoid(s.scale_ > 0 ? rgb / s.scale_ : Vec3f(0.f));
  return s;
}

Spectrum Spectrum::RgbIlluminant(Vec3f rgb) {
  Spectrum s = RgbUnbounded(rgb);
  s.kind_ = Kind::kRgbIlluminant;
  return s;
}

Spectrum Spectrum::Blackbody(float temperature_k, float scale) {
  Spectrum s;
  s.kind_ = Kind::kBlackbody;
  s.temperature_ = temperature_k;
  s.scale_ = scale;
  // Wien's displacement law gives the peak wavelength.
  double lambda_max = 2.8977721e-3 / temperature_k * 1e9;
  s.normalization_ = float(1 / objektiv::Blackbody(lambda_max, temperature_k));
  return s;
}

Spectrum Spectrum::D65(float scale) {
  Spectrum s;
  s.kind_ = Kind::kD65;
  s.scale_ = scale;
  return s;
}

Spectrum Spectrum::Tabulated(std::vector<float> lambdas, std::vector<float> values) {
  Spectrum s;
  s.kind_ = Kind::kTabulated;
  s.scale_ = 1;
  s.lambdas_ = std::make_shared<const std::vector<float>>(std::move(lambdas));
  s.values_ = std::make_shared<const std::vector<float>>(std::move(values));
  return s;
}

float Spectrum::operator()(float lambda) const {
  switch (kind_) {
    case Kind::kConstant:
      return scale_;
    case Kind::kRgbAlbedo:
    case Kind::kRgbUnbounded:
      return scale_ * poly_(lambda);
    case Kind::kRgbIlluminant:
      return scale_ * poly_(lambda) * D65Normalized(lambda);
    case Kind::kBlackbody:
      return scale_ * normalization_ * float(objektiv::Blackbody(lambda, temperature_));
    case Kind::kD65:
      return scale_ * D65Normalized(lambda);
    case Kind::kTabulated: {
      const auto& l = *lambdas_;
      const auto& v = *values_;
      if (lambda <= l.front()) return scale_ * v.front();
      if (lambda >= l.back()) return scale_ * v.back();
      size_t i = size_t(std::upper_bound(l.begin(), l.end(), lambda) - l.begin()) - 1;
      float t = (lambda - l[i]) / (l[i + 1] - l[i]);
      return scale_ * Lerp(t, v[i], v[i + 1]);
    }
  }
  return 0;
}

SampledSpectrum Spectrum::Sample(const SampledWavelengths& w) const {
  // The common kinds are dispatched once for the whole bundle (this is on the hot path).
  SampledSpectrum s;
  switch (kind_) {
    case Kind::kConstant:
      return SampledSpectrum(scale_);
    case Kind::kRgbAlbedo:
    case Kind::kRgbUnbounded:
      for (int i = 0; i < kSpectrumSamples; ++i) s[i] = scale_ * poly_(w[i]);
      return s;
    case Kind::kRgbIlluminant:
      for (int i = 0; i < kSpectrumSamples; ++i) s[i] = scale_ * poly_(w[i]) * D65Normalized(w[i]);
      return s;
    default:
      for (int i = 0; i < kSpectrumSamples; ++i) s[i] = (*this)(w[i]);
      return s;
  }
}

float Spectrum::MaxValue() const {
  switch (kind_) {
    case Kind::kConstant:
      return scale_;
    case Kind::kRgbAlbedo:
    case Kind::kRgbUnbounded:
      return scale_ * poly_.MaxValue();
    default: {
      float m = 0;
      for (float l = kLambdaMin; l <= kLambdaMax; l += 1) m = std::max(m, (*this)(l));
      return m;
    }
  }
}

Spectrum Spectrum::Scaled(float s) const {
  Spectrum r = *this;
  r.scale_ *= s;
  return r;
}

float SpectrumToY(const Spectrum& s) {
  double y = 0;
  for (int l = int(kLambdaMin); l <= int(kLambdaMax); ++l) y += CieXyz(float(l)).y * s(float(l));
  return float(y / CieYIntegral());
}

Vec3f SpectrumToRgb(const Spectrum& s) {
  Vec3d xyz(0.0);
  for (int l = int(kLambdaMin); l <= int(kLambdaMax); ++l) {
    double w = (l == int(kLambdaMin) || l == int(kLambdaMax)) ? 0.5 : 1.0;
    xyz += Vec3d(CieXyz(float(l))) * (w * s(float(l)));
  }
  return ColorSpace::Rec709().ToRGB(Vec3f(xyz / CieYIntegral()));
}

}  // namespace objektiv
