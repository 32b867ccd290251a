// Homogeneous participating media (fog, milk, smoke): a volume with constant absorption and
// scattering coefficients sigma_a and sigma_s (per scene unit, per wavelength), extinction
// sigma_t = sigma_a + sigma_s, single-scattering albedo sigma_s / sigma_t, and a phase function.
//
// Along a ray through it radiance falls as the transmittance T(d) = exp(-sigma_t d) (Beer-Lambert)
// and gains what is scattered into the ray: L(0) = int_0^D T(t) sigma_s int p L_i dw dt + T(D) L(D).
// A path tracer estimates this by free-flight sampling: a distance t with density
// sigma_t exp(-sigma_t t); below D the path scatters there (weight sigma_s T / pdf), otherwise it
// reaches the surface (weight T(D) / P(t >= D)).
//
// Spectral: sigma_t differs between the wavelengths a path carries, and sampling by one of them
// alone would leave the others' estimates with unbounded weights (or none where that one is 0).
// A path samples all its distances with the sigma_t of one wavelength c, chosen uniformly among
// the bundle's when the path first enters a medium, and every wavelength's estimate is weighted
// by the balance heuristic over the n choices of c for the whole path (one-sample spectral MIS,
// as pbrt-v4's volumetric path tracer, with c chosen at random rather than the hero, which keeps
// every wavelength unbiased on its own):
//   estimate_i = f_i(path) / ((1/n) sum_j p_j(path)),
// p_j the density of the path's distances when sampled with wavelength j. The integrator
// carries f_i / p_c and the ratios p_j / p_c as products of each event's factors (MediumSample's
// weight and ratio); per event, with T_j = exp(-sigma_t,j t):
//   scattered at t:      weight_i = sigma_s,i T_i / (sigma_t,c T_c),   ratio_j = sigma_t,j T_j / (sigma_t,c T_c);
//   passed to d_max:     weight_i = T_i / T_c,                         ratio_j = T_j / T_c.
// The denominators are positive (sigma_t,c T_c = sigma_t,c (1 - u) at a sampled t; T_c >= 1 - u
// at a passed d_max), and a wavelength with sigma_t = 0 passes with T = 1.
//
// A medium that only absorbs (sigma_s = 0 at every wavelength: tinted glass, ink) has nothing to
// scatter at: a sampled collision could only end the path, turning the smooth exp(-sigma_t d)
// into a coin toss. There every segment passes, weighted by the transmittance itself
// (weight_i = T_i, ratio_j = 1: no distance was sampled, every wavelength's density is the same),
// which is exact, noise-free, and the estimator Beer-Lambert absorption in a dielectric uses.
#pragma once
#include "base/sampled_spectrum.h"
#include "base/spectrum.h"
#include "scene/phase_function.h"

namespace objektiv {

// The outcome of free-flight sampling along a segment of length d_max (infinite: a ray that
// leaves the scene).
struct MediumSample {
  bool scattered = false;  // a scattering event at `distance` (< d_max); else the segment's end
  float distance = 0;
  // This event's factors of f_i / p_c and of p_j / p_c (see above).
  SampledSpectrum weight, ratio;
};

class HomogeneousMedium {
 public:
  // As Mitsuba 3 gives it: extinction sigma_t and single-scattering albedo (sigma_s = albedo
  // sigma_t), or as absorption and scattering (sigma_t = sigma_a + sigma_s); both times
  // `scale`. Coefficients per scene unit, non-negative, albedo in [0, 1] (the loader checks).
  static HomogeneousMedium FromExtinction(Spectrum sigma_t, Spectrum albedo, float scale, HGPhaseFunction phase,
                                          bool sample_emitters = true) {
    return HomogeneousMedium(std::move(sigma_t), std::move(albedo), true, scale, phase, sample_emitters);
  }
  static HomogeneousMedium FromCoefficients(Spectrum sigma_a, Spectrum sigma_s, float scale, HGPhaseFunction phase,
                                            bool sample_emitters = true) {
    return HomogeneousMedium(std::move(sigma_a), std::move(sigma_s), false, scale, phase, sample_emitters);
  }

  SampledSpectrum SigmaT(const SampledWavelengths& lambda) const {
    return (extinction_ ? a_.Sample(lambda) : a_.Sample(lambda) + b_.Sample(lambda)) * scale_;
  }
  SampledSpectrum SigmaS(const SampledWavelengths& lambda) const {
    return (extinction_ ? a_.Sample(lambda) * b_.Sample(lambda) : b_.Sample(lambda)) * scale_;
  }
  // exp(-sigma_t d) per wavelength; d may be infinite (then 0 where sigma_t > 0, 1 where 0).
  SampledSpectrum Transmittance(float d, const SampledWavelengths& lambda) const;
  // Free-flight sampling over [0, d_max) by the sigma_t of wavelength `channel`, with the number
  // u in [0, 1) (see above).
  MediumSample SampleDistance(float d_max, const SampledWavelengths& lambda, int channel, float u) const;
  const HGPhaseFunction& phase() const { return phase_; }
  // Whether paths scattered inside sample the emitters (next-event estimation with MIS), as
  // Mitsuba 3's sample_emitters; without, only phase sampling finds them.
  bool SamplesEmitters() const { return sample_emitters_; }
  // Whether it scatters at any wavelength (sigma_s > 0 somewhere); if not, SampleDistance never
  // samples a collision and returns the transmittance (see above).
  bool Scatters() const { return scatters_; }

 private:
  HomogeneousMedium(Spectrum a, Spectrum b, bool extinction, float scale, HGPhaseFunction phase, bool sample_emitters)
      : a_(std::move(a)), b_(std::move(b)), extinction_(extinction), scale_(scale), phase_(phase),
        sample_emitters_(sample_emitters), scatters_(b_.MaxValue() > 0 && scale > 0) {}
  // (sigma_t, albedo) if extinction_, else (sigma_a, sigma_s).
  Spectrum a_, b_;
  bool extinction_;
  float scale_;
  HGPhaseFunction phase_;
  bool sample_emitters_;
  bool scatters_;  // b_ is the albedo or sigma_s: either way zero everywhere means no scattering
};

using Medium = HomogeneousMedium;

}  // namespace objektiv
