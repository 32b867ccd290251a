// Phase functions: the angular distribution of light scattered in a medium, a density over the
// sphere of directions (it integrates to 1). Directions follow the BSDFs' convention: wo points
// back along the arriving ray, wi is the new direction, and the deflection angle theta lies
// between the propagation direction -wo and wi (cos theta = -wo . wi). Phase functions are
// reciprocal: p(wo, wi) = p(wi, wo).
//
// Henyey-Greenstein, with mean cosine g in (-1, 1) (g > 0: forward scattering, as fog and milk):
//   p(theta) = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos theta)^(3/2));
// g = 0 is isotropic, 1 / (4 pi). It is sampled exactly (the CDF of cos theta inverts in closed
// form), so the sample's weight p / pdf is 1.
#pragma once
#include <optional>

#include "base/vec.h"

namespace objektiv {

struct PhaseSample {
  Vec3f wi;
  float p = 0;  // the phase function's value, which is also the density (solid angle)
};

class HGPhaseFunction {
 public:
  // g must lie in (-1, 1) (the loader checks; values beyond are clamped to +-0.999).
  explicit HGPhaseFunction(float g = 0);
  float g() const { return g_; }
  float p(const Vec3f& wo, const Vec3f& wi) const;
  PhaseSample Sample(const Vec3f& wo, Vec2f u) const;
  float Pdf(const Vec3f& wo, const Vec3f& wi) const { return p(wo, wi); }

 private:
  float g_;
};

// The Henyey-Greenstein density of the cosine of the deflection angle (per steradian).
float HenyeyGreenstein(float cos_theta, float g);

}  // namespace objektiv
