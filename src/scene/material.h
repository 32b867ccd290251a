// Materials turn textures and parameters at a surface point into a BSDF.
#pragma once
#include <memory>
#include <optional>

#include "scene/bsdf.h"
#include "scene/ior.h"
#include "scene/texture.h"

namespace objektiv {

class Material {
 public:
  virtual ~Material() = default;
  // May reduce the wavelength bundle to its hero (dispersive interfaces).
  virtual BSDF GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const = 0;
  // The shading frame GetBSDF's BSDF shades with at si (its frame()): the shape's, unless a
  // bump or normal map perturbs it. For what needs the normal but no BSDF (the AOVs).
  virtual Frame ShadingFrame(const SurfaceInteraction& si) const { return si.shading; }
  virtual void SetTwoSided(bool v) { two_sided_ = v; }
  // Absorption coefficient (per scene unit) of the medium behind the surface, for
  // Beer-Lambert attenuation of path segments inside closed dielectrics; nullptr if none.
  virtual const Spectrum* Absorption() const { return nullptr; }
  // The share of the rays meeting the surface at si that it stops (a `mask`'s opacity, in
  // [0, 1]); the scene lets the rest pass as if it were not there (Scene::Intersect). 1 for
  // every material but a mask and what holds one.
  virtual float Opacity(const SurfaceInteraction&) const { return 1; }
  // Whether Opacity can be below 1 anywhere (the scene tests only such surfaces).
  virtual bool HasOpacity() const { return false; }
  // How many BSDFs its BSDF mixes (a blend's parts, counted through wrappers): at most
  // kMaxBlendLeaves.
  virtual int Leaves() const { return 1; }
  // Mitsuba 3's `null`: not a surface at all, only the boundary of a medium, which rays pass
  // straight through (the path tracer steps over it; it has no BSDF to sample).
  virtual bool IsNull() const { return false; }
  // Whether light may pass through the surface (glass, a null boundary, what holds one): a
  // medium behind a surface that passes none is never entered.
  virtual bool MayTransmit() const { return false; }

 protected:
  bool two_sided_ = false;
};

// The `null` BSDF (see Material::IsNull). GetBSDF gives a black diffuse BSDF: nothing that
// asks for one should (integrators that do not step over null surfaces refuse such scenes).
class NullMaterial final : public Material {
 public:
  BSDF GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const override;
  bool IsNull() const override { return true; }
  bool MayTransmit() const override { return true; }
};

class DiffuseMaterial final : public Material {
 public:
  explicit DiffuseMaterial(std::shared_ptr<const SpectrumTexture> reflectance) : reflectance_(std::move(reflectance)) {}
  BSDF GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const override;

 private:
  std::shared_ptr<const SpectrumTexture> reflectance_;
};

// Smooth or rough (alpha > 0) dielectric; int_ior may vary with wavelength (dispersion).
class DielectricMaterial final : public Material {
 public:
  DielectricMaterial(IorModel int_ior, double ext_ior, float alpha_u, float alpha_v,
                     std::shared_ptr<const SpectrumTexture> specular_reflectance,
                     std::shared_ptr<const SpectrumTexture> specular_transmittance);
  BSDF GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const override;
  const Spectrum* Absorption() const override { return absorption_ ? &*absorption_ : nullptr; }
  void SetAbsorption(Spectrum sigma_a) { absorption_ = std::move(sigma_a); }
  // (Texture values are not negative: a mean of zero is zero everywhere.)
  bool MayTransmit() const override {
    return !specular_transmittance_ || specular_transmittance_->MeanRgb() != Vec3f(0.f);
  }

 private:
  std::optional<Spectrum> absorption_;
  IorModel int_ior_;
  double ext_ior_;
  float alpha_u_, alpha_v_;
  std::shared_ptr<const SpectrumTexture> specular_reflectance_, specular_transmittance_;
};

// Mitsuba 3's `thindielectric` (ThinDielectricBxDF): int_ior may vary with wavelength, which
// changes only the reflectance (light passes undeviated), so every wavelength is kept.
class ThinDielectricMaterial final : public Material {
 public:
  ThinDielectricMaterial(IorModel int_ior, double ext_ior, std::shared_ptr<const SpectrumTexture> specular_reflectance,
                         std::shared_ptr<const SpectrumTexture> specular_transmittance)
      : int_ior_(std::move(int_ior)), ext_ior_(ext_ior), specular_reflectance_(std::move(specular_reflectance)),
        specular_transmittance_(std::move(specular_transmittance)) {}
  BSDF GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const override;
  bool MayTransmit() const override {
    return !specular_transmittance_ || specular_transmittance_->MeanRgb() != Vec3f(0.f);
  }

 private:
  IorModel int_ior_;
  double ext_ior_;
  std::shared_ptr<const SpectrumTexture> specular_reflectance_, specular_transmittance_;
};

class ConductorMaterial final : public Material {
 public:
  ConductorMaterial(Spectrum eta, Spectrum k, float alpha_u, float alpha_v,
                    std::shared_ptr<const SpectrumTexture> specular_reflectance);
  BSDF GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const override;

 private:
  Spectrum eta_, k_;
  float alpha_u_, alpha_v_;
  std::shared_ptr<const SpectrumTexture> specular_reflectance_;
};

class PlasticMaterial final : public Material {
 public:
  PlasticMaterial(float int_ior, float ext_ior, std::shared_ptr<const SpectrumTexture> diffuse,
                  std::shared_ptr<const SpectrumTexture> specular, bool nonlinear);
  BSDF GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const override;

 private:
  float eta_, fdr_int_, specular_weight_;
  std::shared_ptr<const SpectrumTexture> diffuse_, specular_;
  bool nonlinear_;
};

// Mitsuba 3's `roughplastic` (RoughPlasticBxDF): the coat's tables are computed once here.
class RoughPlasticMaterial final : public Material {
 public:
  RoughPlasticMaterial(float alpha, float int_ior, float ext_ior, std::shared_ptr<const SpectrumTexture> diffuse,
                       std::shared_ptr<const SpectrumTexture> specular, bool nonlinear);
  BSDF GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const override;

 private:
  RoughCoat coat_;
  float specular_weight_;
  std::shared_ptr<const SpectrumTexture> diffuse_, specular_;
  bool nonlinear_;
};

// Mitsuba 3's `principled` (PrincipledBxDF): every parameter but eta may be a texture (the
// scalar ones read as the luminance of the texture's numbers, clamped to [0, 1]); the albedo
// tables for its eta are computed once (and shared by the materials of one eta).
class PrincipledMaterial final : public Material {
 public:
  struct Parameters {
    std::shared_ptr<const SpectrumTexture> base_color, roughness, anisotropic, metallic, spec_trans, spec_tint, sheen,
        sheen_tint, clearcoat, clearcoat_gloss;
    float eta = 1.5f;
    float diffuse_rate = 1, specular_rate = 1, clearcoat_rate = 1;
    bool sample_visible = true;
  };
  explicit PrincipledMaterial(Parameters p) : p_(std::move(p)), tables_(PrincipledTables::For(p_.eta)) {}
  BSDF GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const override;
  bool MayTransmit() const override { return p_.spec_trans && p_.spec_trans->MeanRgb() != Vec3f(0.f); }

 private:
  Parameters p_;
  std::shared_ptr<const PrincipledTables> tables_;
};

// The classic tracer's energy-conserving Blinn-Phong (PhongBxDF): where kd + ks exceeds 1 at a
// wavelength both are scaled down to sum to 1 (the loader warns when the colours as written do).
class PhongMaterial final : public Material {
 public:
  PhongMaterial(std::shared_ptr<const SpectrumTexture> diffuse, std::shared_ptr<const SpectrumTexture> specular,
                float exponent)
      : diffuse_(std::move(diffuse)), specular_(std::move(specular)), exponent_(exponent) {}
  BSDF GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const override;

 private:
  std::shared_ptr<const SpectrumTexture> diffuse_, specular_;
  float exponent_;
};

}  // namespace objektiv
