// Mitsuba 3's `principled` BSDF (Burley's Disney BSDF, 2012/2015), made spectral and energy
// conserving (scene/principled_bxdf.cpp). Local frame, z = shading normal; wo looks toward the
// camera (outside where wo.z > 0).
//
// The model, as Mitsuba 3 builds it (alpha_x = r^2 / a, alpha_y = r^2 a, a = sqrt(1 - 0.9
// anisotropic), both at least 0.001; brdf = (1 - metallic)(1 - spec_trans), bsdf = (1 -
// metallic) spec_trans; w(c) = (1 - c)^5; Schlick(F0, c) = F0 + (1 - F0) w(c)):
//   specular reflection  F D G / (4 |cos_o cos_i|), GGX D, with
//                        F = metallic Schlick(base, c) + (1 - metallic) F_p, c = wo.m, and
//                        F_p = (1 - spec_tint) F_diel(c, eta) + spec_tint Schlick(tint R0, c)
//                        (R0 = ((eta - 1)/(eta + 1))^2); from inside only bsdf F_diel;
//   specular transmission  bsdf sqrt(base) (1 - F_p) D G |wi.m wo.m| / (|cos_i cos_o| (wi.m +
//                        wo.m / eta')^2), / eta'^2 for radiance (as the roughdielectric);
//   clearcoat            0.25 clearcoat Schlick(0.04, c) D_GTR1 G_cc / (4 cos_o cos_i), GTR1 of
//                        alpha = lerp(0.1, 0.001, clearcoat_gloss), G_cc = separable Smith
//                        GGX with alpha 0.25;
//   diffuse              brdf base / pi [(1 - Fi/2)(1 - Fo/2) + Rr (Fo + Fi + Fo Fi (Rr - 1))],
//                        Fo = w(cos_o), Fi = w(cos_i), Rr = 2 r cos_d^2, cos_d = wi.h;
//   sheen                sheen c_sheen w(cos_d), c_sheen = lerp(1, tint, sheen_tint).
//
// Where it is RGB-defined and how it is spectral here: base_color is a reflectance, upsampled
// to a smooth spectrum like every other (scene/texture.h), and every product above is taken
// per sampled wavelength: the metal's Schlick F0 is base(lambda), the transmission's colour
// sqrt(base(lambda)). Mitsuba's tint colour base / luminance(base) is base(lambda) / Y, with Y
// the luminance of the texture's linear RGB at the point (the upsampled spectrum has that
// luminance), clamped to at most 1 per wavelength. The dielectric Fresnel is exact (eta is one
// number: no dispersion); the clearcoat's and the tints' are Schlick's, as Mitsuba.
//
// Deliberate differences from Mitsuba 3, each for energy conservation (Mitsuba's sum of lobes
// reflects more than arrives at grazing angles: its specular, clearcoat, diffuse and sheen are
// added without taking from each other, and Disney's retro-reflective diffuse alone has albedo
// above 1 for rough surfaces):
//   - the clearcoat is a layer: everything under it (front side) is scaled by Tcc(wo) Tcc(wi),
//     Tcc = 1 - 0.25 clearcoat E_cc(mu) (E_cc: the unit lobe's albedo), a transmission by Tcc of
//     its outside direction;
//   - the diffuse and sheen lie under the dielectric specular: scaled by Ts(wo) Ts(wi), Ts = 1 -
//     E_p(mu, alpha_w) per wavelength (E_p: the albedo of the F_p lobe, from tables, alpha_w
//     the GGX roughness projected on w's azimuth);
//   - the diffuse and sheen together are scaled by s(mu_o) s(mu_i), s = min(1, 1 / their
//     white albedo at mu) (PrincipledTables::DiffuseScale): darker than Mitsuba's where Disney's
//     diffuse reflects more than arrives (rough surfaces, toward grazing), unchanged elsewhere;
//     and the sheen is weighted by brdf, not (1 - metallic), so that the glass part stays
//     Fresnel-split;
//   - the transmission takes 1 - F_p (the tinted reflectance) instead of 1 - F_diel, so that
//     reflection plus transmission never exceed 1 (Schlick exceeds the exact Fresnel near
//     grazing by up to 0.036 at eta 1.5);
//   - the tint is clamped to 1 per wavelength (Mitsuba's can be 4.7 for a saturated red);
//   - G is the height-correlated Smith term of the project's other GGX BSDFs (Mitsuba: separable).
// With these the albedo is at most 1 for every parameter (up to the tables' accuracy, ~1e-3):
// the lobes form metallic x metal + (1 - metallic) x [F_p reflection + spec_trans x
// transmission + (1 - spec_trans) x Ts-scaled diffuse], a convex sum of parts each at most 1,
// under a clearcoat that passes what it does not reflect. Reflection is reciprocal (every
// scaling is a product of the same function at wo and wi); transmission is not (its colour and
// Fresnel are those of the outside side), as in Mitsuba. Without spec_trans the back side is
// black (`twosided` for both sides).
//
// Sampling, as Mitsuba: the diffuse (cosine), clearcoat (GTR1's D cos) and specular lobes are
// chosen in proportion brdf : 0.25 clearcoat : 1 (times the sampling rates); the specular lobe
// draws a GGX normal (visible normals with sample_visible, D cos otherwise) and reflects or
// refracts with probabilities 1 - bsdf (1 - F_diel) and bsdf (1 - F_diel) (from inside: F_diel
// and 1 - F_diel). f and pdf are always those of the whole mixture.
#pragma once
#include <optional>

#include "base/sampled_spectrum.h"
#include "scene/bxdf.h"
#include "scene/microfacet.h"
#include "scene/principled_tables.h"

namespace objektiv {

namespace principled {

inline float SchlickWeight(float c) {
  const float m = std::clamp(1 - c, 0.f, 1.f);
  return (m * m) * (m * m) * m;
}
// GTR1 (Berry): D(m) = (a^2 - 1) / (pi ln(a^2) (1 + (a^2 - 1) cos^2)), normalised so that
// int D cos dm = 1; sampled by D cos.
float Gtr1D(float alpha, const Vec3f& m);
Vec3f Gtr1Sample(float alpha, Vec2f u);
// Smith's G1 for GGX of roughness alpha (isotropic), 0 where w sees the back of m.
float SmithGgx1(const Vec3f& w, const Vec3f& m, float alpha);
inline float ClearcoatAlpha(float gloss) { return 0.1f + (0.001f - 0.1f) * gloss; }
// Disney's diffuse factor (f_diff + f_retro, times base / pi) and the sheen's w(cos_d), for
// directions above the surface.
float DisneyDiffuse(const Vec3f& wo, const Vec3f& wi, float roughness);
float SheenWeight(const Vec3f& wo, const Vec3f& wi);

}  // namespace principled

struct PrincipledBxDF {
  const PrincipledTables* tables = nullptr;  // not owned (the material's); eta comes from it
  SampledSpectrum base{0.5f};                // base_color, in [0, 1]
  SampledSpectrum tint{1.f};                 // base / luminance, at most 1
  float roughness = 0.5f, anisotropic = 0, metallic = 0, spec_trans = 0, spec_tint = 0, sheen = 0, sheen_tint = 0,
        clearcoat = 0, clearcoat_gloss = 0;
  float diffuse_rate = 1, specular_rate = 1, clearcoat_rate = 1;  // sampling rates (as Mitsuba)
  bool sample_visible = true;

  // Call after setting the fields above (computes the GGX roughness).
  void Prepare();

  SampledSpectrum f(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const { return Evaluate(wo, wi, mode).f; }
  std::optional<BSDFSample> Sample(const Vec3f& wo, float uc, Vec2f u, TransportMode mode) const;
  float Pdf(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const { return Evaluate(wo, wi, mode).pdf; }
  int Flags() const;
  bool Transmits() const { return (1 - metallic) * spec_trans > 0; }
  // The diffuse and sheen part alone, with its layers' scaling (the classic tracer's ambient).
  SampledSpectrum DiffusePart(const Vec3f& wo, const Vec3f& wi) const;
  const TrowbridgeReitz& distrib() const { return distrib_; }
  float alpha_x() const { return ax_; }
  float alpha_y() const { return ay_; }

  struct Evaluation {
    SampledSpectrum f;
    float pdf = 0;
  };
  Evaluation Evaluate(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const;

 private:
  struct LobeProbabilities {
    float diffuse = 0, clearcoat = 0, specular = 1;
  };
  LobeProbabilities Probabilities(bool front) const;
  float Eta() const { return tables->eta(); }
  float ProjectedAlpha(const Vec3f& w) const;
  float ClearcoatPass(float mu) const;             // Tcc
  SampledSpectrum SpecularPass(const Vec3f& w) const;  // Ts
  SampledSpectrum PlasticFresnel(float c, float f_diel) const;  // F_p
  float SpecularNormalPdf(const Vec3f& wo, const Vec3f& m) const;
  TrowbridgeReitz distrib_;
  float ax_ = 0.25f, ay_ = 0.25f;
};

}  // namespace objektiv
