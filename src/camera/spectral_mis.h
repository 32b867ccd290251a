// Spectral multiple importance sampling through a dispersive lens. Each wavelength takes its
// own path through dispersive glass, so a camera ray made for the sample's hero wavelength is,
// for another wavelength k of the sample, a ray whose film point lies elsewhere (x_k, where the
// lens at lambda_k maps it back). Instead of dropping the other wavelengths (pbrt-v4's way,
// which leaves colour noise), the one world ray serves all four, each wavelength weighted as
// one of four sampling techniques (one per wavelength as the hero) under the balance heuristic
// (Wilkie et al. 2014, "Hero Wavelength Spectral Sampling"). In the ray's etendue measure,
// which lossless lenses conserve at every wavelength, technique j (film point from the pixel
// filter f, aim point u from the pupil bound's density p_u, G = cos^4 / dz^2 their geometry)
// has density f(x_j) p_u(u_j | x_j) / G_j up to the filter's constant, and the estimate of
// wavelength k, times the hero's filter weight f(x_0) / pdf(x_0), is
//   L_k T_k s / c(x_k) * f(x_k) / ((1/4) sum_j f(x_j) p_u(u_j | x_j) / G_j),
// T_k the lens's transmittance at lambda_k, s the exposure scale, c the chief-ray factor of the
// camera's vignetting mode. A lens without dispersion has every x_j, u_j alike, and this is
// the usual weight T s G / (c p_u). Any positive f keeps it unbiased (the weights sum to one
// over the techniques wherever one can make the ray).
#pragma once
#include <array>

#include "base/sampled_spectrum.h"
#include "base/vec.h"

namespace objektiv {

// The camera's part, per wavelength k of the sample: its film point `shift[k]` pixels from the
// sample's, `numerator[k]` = T_k s / c(x_k) (0 where the ray does not get through at lambda_k),
// `density[k]` = p_u(u_k | x_k) / G_k.
struct SpectralMisTerms {
  std::array<Vec2f, kSpectrumSamples> shift{};
  SampledSpectrum numerator{0.f};
  std::array<float, kSpectrumSamples> density{};
};

// The weights with the pixel filter `filter` (its value at an offset from the pixel's centre),
// the sample's own film point lying `offset` from it.
template <typename Filter>
SampledSpectrum SpectralMisWeight(const SpectralMisTerms& t, Vec2f offset, const Filter& filter) {
  std::array<float, kSpectrumSamples> f;
  float sum = 0;
  for (int k = 0; k < kSpectrumSamples; ++k) {
    f[k] = filter(offset + t.shift[k]);
    sum += f[k] * t.density[k];
  }
  SampledSpectrum w(0.f);
  if (!(sum > 0)) return w;
  for (int k = 0; k < kSpectrumSamples; ++k) w[k] = f[k] * t.numerator[k] * kSpectrumSamples / sum;
  return w;
}

}  // namespace objektiv
