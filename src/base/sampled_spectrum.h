// Spectral quantities carried along a path: values at a bundle of kSpectrumSamples wavelengths.
// The wavelengths are chosen with the hero-wavelength scheme (Wilkie et al. 2014): one
// importance-sampled wavelength and the others at equal offsets in the sampling CDF, so
// that the four stratify the visible range. Four is enough to make colour noise small and
// maps to one SSE register; dispersive interfaces keep only the hero (TerminateSecondary).
#pragma once
#include <array>
#include <cmath>

#include "base/vec.h"

namespace objektiv {

constexpr int kSpectrumSamples = 4;

class SampledSpectrum {
 public:
  SampledSpectrum() : v_{} {}
  explicit SampledSpectrum(float c) : v_{c, c, c, c} {}

  float operator[](int i) const { return v_[i]; }
  // Through a float pointer: GCC binds a reference to a vector element, clang does not.
  float& operator[](int i) { return reinterpret_cast<float*>(&v_)[i]; }

#define OBJEKTIV_SS_OP(op)                                                     \
  SampledSpectrum& operator op##=(const SampledSpectrum& o) {                  \
    v_ op## = o.v_;                                                            \
    return *this;                                                              \
  }                                                                            \
  SampledSpectrum operator op(const SampledSpectrum& o) const {                \
    SampledSpectrum r = *this;                                                 \
    return r op## = o;                                                         \
  }
  OBJEKTIV_SS_OP(+)
  OBJEKTIV_SS_OP(-)
  OBJEKTIV_SS_OP(*)
#undef OBJEKTIV_SS_OP

  SampledSpectrum operator*(float s) const {
    SampledSpectrum r = *this;
    r.v_ *= s;
    return r;
  }
  SampledSpectrum& operator*=(float s) {
    v_ *= s;
    return *this;
  }
  SampledSpectrum operator/(float s) const { return *this * (1 / s); }
  // Component-wise division; 0 where the divisor is 0.
  SampledSpectrum SafeDiv(const SampledSpectrum& d) const {
    SampledSpectrum r;
    for (int i = 0; i < kSpectrumSamples; ++i) r.v_[i] = d.v_[i] != 0 ? v_[i] / d.v_[i] : 0;
    return r;
  }

  bool IsBlack() const {
    for (int i = 0; i < kSpectrumSamples; ++i)
      if (v_[i] != 0) return false;
    return true;
  }
  float Max() const { return std::max(std::max(v_[0], v_[1]), std::max(v_[2], v_[3])); }
  float Average() const { return (v_[0] + v_[1] + v_[2] + v_[3]) * 0.25f; }
  bool HasNaN() const {
    for (int i = 0; i < kSpectrumSamples; ++i)
      if (std::isnan(v_[i])) return true;
    return false;
  }
  bool HasInf() const {
    for (int i = 0; i < kSpectrumSamples; ++i)
      if (std::isinf(v_[i])) return true;
    return false;
  }

 private:
  // A GCC vector of four floats: the SysV ABI passes and returns it in one SSE register. (A
  // plain array of four floats travels in two, and reassembling those through memory stalled
  // on store forwarding after every call that returns a spectrum.)
  typedef float Vector4 __attribute__((vector_size(16)));
  static_assert(kSpectrumSamples == 4);
  Vector4 v_;
};

inline SampledSpectrum operator*(float s, const SampledSpectrum& v) { return v * s; }
inline SampledSpectrum Exp(const SampledSpectrum& s) {
  SampledSpectrum r;
  for (int i = 0; i < kSpectrumSamples; ++i) r[i] = std::exp(s[i]);
  return r;
}

class SampledWavelengths {
 public:
  // Importance-sample the visible range with pdf ~ 1/cosh^2(0.0072 (lambda - 538)) over
  // [360, 830] (roughly the sum of the matching functions), as pbrt-v4 does.
  static SampledWavelengths SampleVisible(float u);
  // Uniform over [lmin, lmax] (for tests).
  static SampledWavelengths SampleUniform(float u, float lmin = 360, float lmax = 830);
  // A single known wavelength with pdf 1, secondary ones terminated (for lens analysis and tests).
  static SampledWavelengths Single(float lambda);

  float operator[](int i) const { return lambda_[i]; }
  float Pdf(int i) const { return pdf_[i]; }
  SampledSpectrum PdfSpectrum() const;

  // Keep only the hero wavelength (after a wavelength-dependent direction change).
  void TerminateSecondary();
  bool SecondaryTerminated() const;

 private:
  std::array<float, kSpectrumSamples> lambda_{}, pdf_{};
};

float VisibleWavelengthsPdf(float lambda);
float SampleVisibleWavelength(float u);

}  // namespace objektiv
