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

MediumSample HomogeneousMedium::SampleDistance(float d_max, const SampledWavelengths& lambda, int channel,
                                               float u) const {
  if (!scatters_) {  // a pure absorber: nothing to sample (see the header)
    MediumSample ms;
    ms.distance = d_max;
    ms.weight = Transmittance(d_max, lambda);
    ms.ratio = SampledSpectrum(1.f);
    return ms;
  }
  const SampledSpectrum st = SigmaT(lambda);
  const int c = channel;
  const float u_t = std::min(u, 0x1.fffffep-1f);
  const float t = st[c] > 0 ? -std::log1p(-u_t) / st[c] : std::numeric_limits<float>::infinity();
  MediumSample ms;
  SampledSpectrum tr;
  if (t < d_max) {
    for (int i = 0; i < kSpectrumSamples; ++i) tr[i] = Attenuation(st[i], t);
    // sigma_t,c T_c(t) = sigma_t,c (1 - u_t) > 0.
    const float pdf_c = st[c] * tr[c];
    ms.scattered = true;
    ms.distance = t;
    ms.weight = SigmaS(lambda) * tr / pdf_c;
    ms.ratio = st * tr / pdf_c;
    return ms;
  }
  // P_c(t >= d_max) = T_c(d_max) >= 1 - u_t > 0: wavelength c reached d_max.
  for (int i = 0; i < kSpectrumSamples; ++i) tr[i] = Attenuation(st[i], d_max);
  ms.distance = d_max;
  ms.weight = tr / tr[c];
  ms.ratio = ms.weight;
  return ms;
}

}  // namespace objektiv
