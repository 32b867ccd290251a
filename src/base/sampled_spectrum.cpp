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
  SampledWavelengths w;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    float up = u + float(i) / kSpectrumSamples;
    if (up > 1) up -= 1;
    w.lambda_[i] = SampleVisibleWavelength(up);
    w.pdf_[i] = VisibleWavelengthsPdf(w.lambda_[i]);
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
