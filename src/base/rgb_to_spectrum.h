// Smooth, energy-bounded spectra from RGB (Jakob and Hanika 2019, "A Low-Dimensional
// Function Space for Efficient Spectral Upsampling"): a reflectance is the sigmoid of a
// quadratic in wavelength, s(l) = S(c0 t^2 + c1 t + c2) with t = (l - 360) / 470 and
// S(x) = 1/2 + x / (2 sqrt(1 + x^2)). The coefficients for an RGB in [0,1]^3 come from a
// table fitted at build time (tools/rgb2spec_gen.cpp) for linear Rec.709 under D65.
#pragma once
#include <cmath>

#include "base/sampled_spectrum.h"

namespace objektiv {

struct SigmoidPolynomial {
  float c0 = 0, c1 = 0, c2 = 0;

  static float Sigmoid(float x) {
    if (std::isinf(x)) return x > 0 ? 1.f : 0.f;
    return 0.5f + x / (2 * std::sqrt(1 + x * x));
  }
  float operator()(float lambda) const {
    float t = (lambda - 360.f) * (1.f / 470.f);
    return Sigmoid((c0 * t + c1) * t + c2);
  }
  SampledSpectrum Sample(const SampledWavelengths& w) const {
    SampledSpectrum s;
    for (int i = 0; i < kSpectrumSamples; ++i) s[i] = (*this)(w[i]);
    return s;
  }
  // Maximum of the sigmoid over [360, 830] (at an endpoint or the parabola's vertex).
  float MaxValue() const;
};

// Coefficients for an RGB with components in [0, 1] (clamped otherwise).
SigmoidPolynomial RgbToSigmoid(Vec3f rgb);

constexpr int kRgbTableRes = 64;
// The nonlinear z (brightness) axis of the table: smoothstep(smoothstep(i / (res - 1))),
// denser near black and near full brightness where the coefficients change fastest.
inline float RgbTableZ(int i) {
  auto smoothstep = [](double x) { return x * x * (3 - 2 * x); };
  return float(smoothstep(smoothstep(double(i) / (kRgbTableRes - 1))));
}

}  // namespace objektiv
