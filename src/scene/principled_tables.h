// The directional albedos the `principled` BSDF (scene/principled_bxdf.h) needs to be energy
// conserving, integrated numerically once and interpolated (scene/principled_tables.cpp).
//
// For a GGX lobe of roughness alpha seen at mu = cos(theta_o), with visible normals m drawn from
// D_wo(m) = G1(wo) D(m) |wo.m| / mu and wi = reflect(wo, m), the albedo
// int F D G / (4 mu cos_i) cos_i dwi is the mean of F(wo.m) G(wo, wi) / G1(wo). Tabulated:
//   DielectricAlbedo(mu, alpha): F = the exact dielectric Fresnel of the material's eta;
//   SchlickScale/SchlickBias(mu, alpha): F = Schlick's F0 + (1 - F0) (1 - c)^5 splits into
//     F0 * mean((1 - (1 - c)^5) G/G1) + mean((1 - c)^5 G/G1), so a coloured F0 needs no table;
//   ClearcoatAlbedo(mu, gloss): the clearcoat lobe (GTR1, Schlick F0 = 0.04, separable Smith
//     G with alpha 0.25) with unit weight, integrated by its own (D cos) sampling;
//   DiffuseScale(mu, roughness, sheen): s(mu) = min(1, 1 / (A_diff(mu; r) + sheen A_sheen(mu))),
//     from the directional albedos of Disney's diffuse (with retro-reflection, above 1 for rough
//     surfaces) and of the sheen lobe for a white base. The BSDF scales the two by s(mu_o)
//     s(mu_i): reciprocal, and as s(mu_i) <= 1 the albedo at mu_o is at most s(mu_o) A(mu_o) <= 1,
//     while directions whose albedo is below 1 keep nearly all of it.
// alpha spans [0, 3.2] (the anisotropic principled stretches r^2 up to r^2 / sqrt(0.1)).
#pragma once
#include <memory>
#include <vector>

namespace objektiv {

class PrincipledTables {
 public:
  explicit PrincipledTables(float eta);  // eta > 1
  // The tables of eta, shared by every material of that eta (made once, ~0.1 s each).
  static std::shared_ptr<const PrincipledTables> For(float eta);

  float eta() const { return eta_; }
  float DielectricAlbedo(float mu, float alpha) const;
  float SchlickScale(float mu, float alpha) const;
  float SchlickBias(float mu, float alpha) const;
  static float ClearcoatAlbedo(float mu, float gloss);
  static float DiffuseScale(float mu, float roughness, float sheen);

 private:
  float eta_;
  std::vector<float> dielectric_;  // [alpha node][mu node]
};

}  // namespace objektiv
