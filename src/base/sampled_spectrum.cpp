#include "base/sampled_spectrum.h"

#include "base/cie.h"

namespace objektiv {

float VisibleWavelengthsPdf(float lambda) {
  if (lambda < kLambdaMin || lambda > kLambdaMax) return 0;
  return 0.0039398042f / Sqr(std::cosh(0.0072f * (lambda - 538)));
}

float SampleVisibleWavelength(float u) {
  // Inverse of the CDF of the cosh^-2 density over [360, 830].
  return 538 - 138.888889f * std::atanh(0.85691062f - 1.82750197f * u);
}

SampledWavelengths SampledWavelengths::SampleVisible(float u) {
  // With y = 0.85691062 - 1.82750197 u the sample is 538 - 138.888889 atanh(y), and since
  // 0.0072 * 138.888889 = 1, cosh^2(0.0072 (lambda - 538)) = cosh^2(atanh y) = 1 / (1 - y^2):
  // the density needs no transcendental function, the sample one logarithm.
  SampledWavelengths w;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    float up = u + float(i) / kSpectrumSamples;
    if (up > 1) up -= 1;
    float y = 0.85691062f - 1.82750197f * up;
    w.lambda_[i] = Clamp(538 - 69.4444444f * std::log((1 + y) / (1 - y)), kLambdaMin, kLambdaMax);
    w.pdf_[i] = 0.0039398042f * (1 - y * y);
  }
  return w;
}

SampledWavelengths SampledWavelengths::SampleUniform(float u, float lmin, float lmax) {
  SampledWavelengths w;
  float delta = (lmax - lmin) / kSpectrumSamples;
  w.lambda_[0] = Lerp(u, lmin, lmax);
  for (int i = 1; i < kSpectrumSamples; ++i) {
    w.lambda_[i] = w.lambda_[i - 1] + delta;
    if (w.lambda_[i] > lmax) w.lambda_[i] = lmin + (w.lambda_[i] - lmax);
  }
  for (int i = 0; i < kSpectrumSamples; ++i) w.pdf_[i] = 1 / (lmax - lmin);
  return w;
}

SampledWavelengths SampledWavelengths::Single(float lambda) {
  SampledWavelengths w;
  w.lambda_.fill(lambda);
  w.pdf_.fill(0);
  w.pdf_[0] = 1;
  return w;
}

SampledSpectrum SampledWavelengths::PdfSpectrum() const {
  SampledSpectrum s;
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = pdf_[i];
  return s;
}

void SampledWavelengths::TerminateSecondary() {
  if (SecondaryTerminated()) return;
  for (int i = 1; i < kSpectrumSamples; ++i) pdf_[i] = 0;
  // The hero now carries the whole estimate: its pdf is divided by the bundle size.
  pdf_[0] /= kSpectrumSamples;
}

bool SampledWavelengths::SecondaryTerminated() const {
  for (int i = 1; i < kSpectrumSamples; ++i)
    if (pdf_[i] != 0) return false;
  return true;
}

}  // namespace objektiv
