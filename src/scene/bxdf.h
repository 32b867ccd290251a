// Scattering functions in the local shading frame (z = shading normal). Every BxDF returns
// f * |cos(theta_i)| from Sample only through BSDFSample.f (without the cosine); the
// integrator multiplies by the cosine itself.
#pragma once
#include <optional>

#include "base/sampled_spectrum.h"
#include "scene/microfacet.h"
#include "scene/rough_coat.h"

namespace objektiv {

enum BxDFFlags : int {
  kReflection = 1,
  kTransmission = 2,
  kDiffuse = 4,
  kGlossy = 8,
  kSpecular = 16,
};

enum class TransportMode { kRadiance, kImportance };

struct BSDFSample {
  SampledSpectrum f;
  Vec3f wi;
  float pdf = 0;
  int flags = 0;
  float eta = 1;  // relative index crossed (for Russian roulette's radiance scaling)
  bool IsSpecular() const { return flags & kSpecular; }
  bool IsTransmission() const { return flags & kTransmission; }
};

// Lambertian reflection (front side only; `twosided` makes it two-sided).
struct DiffuseBxDF {
  SampledSpectrum R;
  SampledSpectrum f(const Vec3f& wo, const Vec3f& wi) const;
  std::optional<BSDFSample> Sample(const Vec3f& wo, float uc, Vec2f u) const;
  float Pdf(const Vec3f& wo, const Vec3f& wi) const;
  int Flags() const { return R.IsBlack() ? 0 : kReflection | kDiffuse; }
};

// Dielectric interface, smooth or rough (GGX): reflection and refraction weighted by Fresnel.
// eta = n_inside / n_outside (inside = against the normal).
struct DielectricBxDF {
  float eta = 1.5f;
  TrowbridgeReitz distrib;
  SampledSpectrum reflect_scale{1.f}, transmit_scale{1.f};
  SampledSpectrum f(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const;
  std::optional<BSDFSample> Sample(const Vec3f& wo, float uc, Vec2f u, TransportMode mode) const;
  float Pdf(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const;
  int Flags() const;
};

// Conductor with complex index eta + i k per wavelength, smooth or rough (GGX).
struct ConductorBxDF {
  SampledSpectrum eta, k, scale{1.f};
  TrowbridgeReitz distrib;
  SampledSpectrum f(const Vec3f& wo, const Vec3f& wi) const;
  std::optional<BSDFSample> Sample(const Vec3f& wo, float uc, Vec2f u) const;
  float Pdf(const Vec3f& wo, const Vec3f& wi) const;
  int Flags() const { return distrib.EffectivelySmooth() ? kReflection | kSpecular : kReflection | kGlossy; }
};

// Smooth plastic (as Mitsuba's `plastic`): a diffuse base under a smooth dielectric coat,
// with the coat's internal reflections summed in closed form.
struct PlasticBxDF {
  float eta = 1.49f;
  float fdr_int = 0;             // diffuse Fresnel reflectance seen from inside the coat
  float specular_sampling_weight = 0.5f;
  SampledSpectrum diffuse, specular{1.f};
  bool nonlinear = false;
  SampledSpectrum f(const Vec3f& wo, const Vec3f& wi) const;
  std::optional<BSDFSample> Sample(const Vec3f& wo, float uc, Vec2f u) const;
  float Pdf(const Vec3f& wo, const Vec3f& wi) const;
  int Flags() const { return kReflection | kDiffuse | kSpecular; }
};

// Rough plastic (Mitsuba 3's `roughplastic`): a Lambertian base under a rough dielectric coat
// (scene/rough_plastic_bxdf.cpp). The coat reflects its GGX microfacet lobe, specular * F D G /
// (4 cos_o cos_i); the base's light enters and leaves through it, scaled by what the coat lets
// through at each end, T(mu_i) T(mu_o), and bounces between base and coat (a geometric series
// in the coat's internal reflectance): diffuse / (1 - Fdr) T_i T_o / (pi eta^2). With the
// internal reflectance RoughCoat derives, the albedo is at most 1 and exactly 1 for a white
// base (and specular 1); as alpha -> 0 it becomes PlasticBxDF. Front side only.
struct RoughPlasticBxDF {
  const RoughCoat* coat = nullptr;  // not owned (the material's)
  float specular_sampling_weight = 0.5f;
  SampledSpectrum diffuse, specular{1.f};
  bool nonlinear = false;
  SampledSpectrum f(const Vec3f& wo, const Vec3f& wi) const;
  std::optional<BSDFSample> Sample(const Vec3f& wo, float uc, Vec2f u) const;
  float Pdf(const Vec3f& wo, const Vec3f& wi) const;
  int Flags() const { return kReflection | kGlossy | (diffuse.IsBlack() ? 0 : kDiffuse); }
  // The base's part alone (what the classic tracer's ambient term multiplies).
  SampledSpectrum DiffusePart(const Vec3f& wo, const Vec3f& wi) const;
  float SpecularProbability(float cos_o) const;  // of sampling the coat's lobe at wo

 private:
  struct Evaluation {
    SampledSpectrum f;
    float pdf = 0;
  };
  Evaluation Evaluate(const Vec3f& wo, const Vec3f& wi) const;
};

// A thin dielectric sheet (Mitsuba 3's `thindielectric`: a window pane): light reflects off it or
// passes straight through, undeviated, with the reflections between the sheet's two faces summed
// in closed form: R + T^2 R (1 + R^2 + R^4 + ...) = 2R / (1 + R) of Fresnel's R at each face
// (scene/thin_dielectric_bxdf.cpp). Purely specular; the same from both sides.
struct ThinDielectricBxDF {
  SampledSpectrum eta{1.5f};  // n_sheet / n_outside per wavelength (no dispersion of direction)
  SampledSpectrum reflect_scale{1.f}, transmit_scale{1.f};
  SampledSpectrum f(const Vec3f&, const Vec3f&) const { return {}; }
  std::optional<BSDFSample> Sample(const Vec3f& wo, float uc, Vec2f u) const;
  float Pdf(const Vec3f&, const Vec3f&) const { return 0; }
  int Flags() const { return kReflection | kTransmission | kSpecular; }
  // The sheet's reflectance (both faces, every inner reflection) at |cos theta| = cos_o.
  SampledSpectrum Reflectance(float cos_o) const;
};

// Energy-conserving Blinn-Phong (the classic tracer's `phong`): a Lambertian lobe kd / pi and a
// normalised half-vector lobe ks (n+2)(n+4) / (8 pi (2^(-n/2) + n)) cos^n(theta_h), whose
// directional albedo is exactly ks at normal incidence and less elsewhere, so kd + ks <= 1
// never reflects more than arrives (scene/phong_bxdf.cpp). Front side only, like the diffuse.
struct PhongBxDF {
  SampledSpectrum kd, ks;
  float exponent = 30;
  SampledSpectrum f(const Vec3f& wo, const Vec3f& wi) const;
  std::optional<BSDFSample> Sample(const Vec3f& wo, float uc, Vec2f u) const;
  float Pdf(const Vec3f& wo, const Vec3f& wi) const;
  int Flags() const;
  float SpecularProbability() const;  // of choosing the lobe of ks when sampling

 private:
  struct Evaluation {
    SampledSpectrum f;
    float pdf = 0;
  };
  Evaluation Evaluate(const Vec3f& wo, const Vec3f& wi) const;
};

}  // namespace objektiv
