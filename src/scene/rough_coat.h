// A rough dielectric coat (GGX, relative index eta = n_coat / n_outside) over a base, as the
// `roughplastic` material sees it: the coat's directional reflectance R(mu) from outside,
// tabulated over mu = cos(theta), and what follows from it for light inside the coat
// (scene/rough_coat.cpp).
#pragma once
#include <vector>

#include "scene/microfacet.h"

namespace objektiv {

class RoughCoat {
 public:
  // alpha > 0 (GGX roughness), eta > 0.
  RoughCoat(float alpha, float eta);

  const TrowbridgeReitz& distrib() const { return distrib_; }
  float eta() const { return eta_; }
  // The coat's directional reflectance from outside: the integral of its microfacet
  // reflection f_r(wo, wi) cos(theta_i) over the hemisphere, at cos(theta_o) = mu.
  float Reflectance(float mu) const;
  // What enters the coat at mu: all that it does not reflect (the microfacet model's
  // masking loss counted as entering, as Mitsuba does).
  float Transmittance(float mu) const { return 1 - Reflectance(mu); }
  // The share of diffuse light inside the coat that it sends back to the base:
  // 1 - (1/eta^2) 2 int T(mu) mu dmu. By the reciprocity of transmission through the
  // interface, a diffuse radiance inside escapes in the share (1/eta^2) times the cosine-
  // weighted mean of T from outside; taking the internal reflectance as the rest is what
  // makes a white base under the coat reflect exactly all the light that arrives.
  float InternalReflectance() const { return internal_reflectance_; }

 private:
  TrowbridgeReitz distrib_;
  float eta_;
  std::vector<float> table_;  // R at mu = (i / (n - 1))^2, denser toward grazing
  float internal_reflectance_ = 0;
};

}  // namespace objektiv
