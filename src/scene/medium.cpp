#include "scene/medium.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace objektiv {

namespace {
// exp(-s d), with 0 * infinity taken as 0 (no extinction: nothing is lost however far).
float Attenuation(float s, float d) { return s > 0 ? std::exp(-s * d) : 1.f; }
}  // namespace

SampledSpectrum HomogeneousMedium::Transmittance(float d, const SampledWavelengths& lambda) const {
  const SampledSpectrum st = SigmaT(lambda);
  SampledSpectrum tr;
  for (int i = 0; i < kSpectrumSamples; ++i) tr[i] = Attenuation(st[i], d);
  return tr;
}

MediumSample HomogeneousMedium::SampleDistance(float d_max, const SampledWavelengths& lambda, float u) const {
  const SampledSpectrum st = SigmaT(lambda);
  // The wavelength that samples, and the number left for its distance.
  const int c = std::min(int(u * kSpectrumSamples), kSpectrumSamples - 1);
  const float u_t = std::min(u * kSpectrumSamples - c, 0x1.fffffep-1f);
  const float t = st[c] > 0 ? -std::log1p(-u_t) / st[c] : std::numeric_limits<float>::infinity();
  MediumSample ms;
  SampledSpectrum tr;
  if (t < d_max) {
    // pdf(t) = mean of sigma_t,j T_j(t); its sampling wavelength's term alone is
    // sigma_t,c (1 - u_t) > 0, so the mean is positive.
    float pdf = 0;
    for (int i = 0; i < kSpectrumSamples; ++i) {
      tr[i] = Attenuation(st[i], t);
      pdf += st[i] * tr[i];
    }
    pdf /= kSpectrumSamples;
    ms.scattered = true;
    ms.distance = t;
    ms.weight = SigmaS(lambda) * tr / pdf;
    return ms;
  }
  // P(t >= d_max) = mean of T_j(d_max); positive since the sampling wavelength reached d_max.
  float p = 0;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    tr[i] = Attenuation(st[i], d_max);
    p += tr[i];
  }
  p /= kSpectrumSamples;
  ms.distance = d_max;
  ms.weight = p > 0 ? tr / p : SampledSpectrum(0.f);
  return ms;
}

}  // namespace objektiv
