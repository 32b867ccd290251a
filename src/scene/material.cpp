#include "scene/material.h"

#include "scene/fresnel.h"

#include <algorithm>
#include <cmath>

namespace objektiv {

namespace {
// A reflectance texture's value at si, each wavelength clamped to [0, 1] (a bitmap may hold more).
SampledSpectrum Reflectance(const SpectrumTexture& t, const SurfaceInteraction& si, const SampledWavelengths& lambda) {
  SampledSpectrum r = t.Evaluate(si.uv, lambda);
  for (int i = 0; i < kSpectrumSamples; ++i) r[i] = Clamp(r[i], 0, 1);
  return r;
}
}  // namespace

BSDF NullMaterial::GetBSDF(const SurfaceInteraction& si, SampledWavelengths&) const {
  return BSDF(si.shading, DiffuseBxDF{SampledSpectrum(0.f)}, false);
}

BSDF DiffuseMaterial::GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const {
  return BSDF(si.shading, DiffuseBxDF{Reflectance(*reflectance_, si, lambda)}, two_sided_);
}

DielectricMaterial::DielectricMaterial(IorModel int_ior, double ext_ior, float alpha_u, float alpha_v,
                                       std::shared_ptr<const SpectrumTexture> specular_reflectance,
                                       std::shared_ptr<const SpectrumTexture> specular_transmittance)
    : int_ior_(int_ior), ext_ior_(ext_ior), alpha_u_(alpha_u), alpha_v_(alpha_v),
      specular_reflectance_(std::move(specular_reflectance)), specular_transmittance_(std::move(specular_transmittance)) {}

BSDF DielectricMaterial::GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const {
  // A wavelength-dependent index bends each wavelength its own way: only the hero survives.
  if (int_ior_.IsDispersive()) lambda.TerminateSecondary();
  DielectricBxDF b;
  b.eta = float(int_ior_(lambda[0]) / ext_ior_);
  b.distrib = TrowbridgeReitz(alpha_u_, alpha_v_);
  b.reflect_scale = specular_reflectance_->Evaluate(si.uv, lambda);
  b.transmit_scale = specular_transmittance_->Evaluate(si.uv, lambda);
  return BSDF(si.shading, b, true);
}

BSDF ThinDielectricMaterial::GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const {
  ThinDielectricBxDF b;
  for (int i = 0; i < kSpectrumSamples; ++i) b.eta[i] = float(int_ior_(lambda[i]) / ext_ior_);
  b.reflect_scale = specular_reflectance_->Evaluate(si.uv, lambda);
  b.transmit_scale = specular_transmittance_->Evaluate(si.uv, lambda);
  return BSDF(si.shading, b, true);
}

ConductorMaterial::ConductorMaterial(Spectrum eta, Spectrum k, float alpha_u, float alpha_v,
                                     std::shared_ptr<const SpectrumTexture> specular_reflectance)
    : eta_(std::move(eta)), k_(std::move(k)), alpha_u_(alpha_u), alpha_v_(alpha_v),
      specular_reflectance_(std::move(specular_reflectance)) {}

BSDF ConductorMaterial::GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const {
  ConductorBxDF b;
  b.eta = eta_.Sample(lambda);
  b.k = k_.Sample(lambda);
  b.scale = specular_reflectance_->Evaluate(si.uv, lambda);
  b.distrib = TrowbridgeReitz(alpha_u_, alpha_v_);
  return BSDF(si.shading, b, two_sided_);
}

namespace {
// The share of sampling given to the coat: its colour's mean against the base's (as Mitsuba).
float SpecularSamplingWeight(const SpectrumTexture& diffuse, const SpectrumTexture& specular) {
  const Vec3f dm = diffuse.MeanRgb(), sm = specular.MeanRgb();
  const float d = dm.x + dm.y + dm.z, s = sm.x + sm.y + sm.z;
  return d + s > 0 ? s / (d + s) : 0.5f;
}
}  // namespace

PlasticMaterial::PlasticMaterial(float int_ior, float ext_ior, std::shared_ptr<const SpectrumTexture> diffuse,
                                 std::shared_ptr<const SpectrumTexture> specular, bool nonlinear)
    : eta_(int_ior / ext_ior), diffuse_(std::move(diffuse)), specular_(std::move(specular)), nonlinear_(nonlinear) {
  fdr_int_ = FresnelDiffuseReflectance(1 / eta_);
  specular_weight_ = SpecularSamplingWeight(*diffuse_, *specular_);
}

BSDF PlasticMaterial::GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const {
  PlasticBxDF b;
  b.eta = eta_;
  b.fdr_int = fdr_int_;
  b.specular_sampling_weight = specular_weight_;
  b.diffuse = Reflectance(*diffuse_, si, lambda);
  b.specular = specular_->Evaluate(si.uv, lambda);
  b.nonlinear = nonlinear_;
  return BSDF(si.shading, b, two_sided_);
}

RoughPlasticMaterial::RoughPlasticMaterial(float alpha, float int_ior, float ext_ior,
                                           std::shared_ptr<const SpectrumTexture> diffuse,
                                           std::shared_ptr<const SpectrumTexture> specular, bool nonlinear)
    : coat_(alpha, int_ior / ext_ior), specular_weight_(SpecularSamplingWeight(*diffuse, *specular)),
      diffuse_(std::move(diffuse)), specular_(std::move(specular)), nonlinear_(nonlinear) {}

BSDF RoughPlasticMaterial::GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const {
  RoughPlasticBxDF b;
  b.coat = &coat_;
  b.specular_sampling_weight = specular_weight_;
  b.diffuse = Reflectance(*diffuse_, si, lambda);
  b.specular = specular_->Evaluate(si.uv, lambda);
  b.nonlinear = nonlinear_;
  return BSDF(si.shading, b, two_sided_);
}

namespace {
float ScalarParameter(const SpectrumTexture& t, Vec2f uv) {
  const float v = Luminance(t.Rgb(uv));
  return std::isnan(v) ? 0.f : std::clamp(v, 0.f, 1.f);
}
}  // namespace

BSDF PrincipledMaterial::GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const {
  PrincipledBxDF b;
  b.tables = tables_.get();
  b.base = Reflectance(*p_.base_color, si, lambda);
  // Mitsuba's tint colour base / luminance(base), per wavelength (see PrincipledBxDF).
  const float lum = Luminance(p_.base_color->Rgb(si.uv));
  for (int i = 0; i < kSpectrumSamples; ++i) b.tint[i] = lum > 0 ? std::min(1.f, b.base[i] / lum) : 1.f;
  b.roughness = ScalarParameter(*p_.roughness, si.uv);
  b.anisotropic = ScalarParameter(*p_.anisotropic, si.uv);
  b.metallic = ScalarParameter(*p_.metallic, si.uv);
  b.spec_trans = ScalarParameter(*p_.spec_trans, si.uv);
  b.spec_tint = ScalarParameter(*p_.spec_tint, si.uv);
  b.sheen = ScalarParameter(*p_.sheen, si.uv);
  b.sheen_tint = ScalarParameter(*p_.sheen_tint, si.uv);
  b.clearcoat = ScalarParameter(*p_.clearcoat, si.uv);
  b.clearcoat_gloss = ScalarParameter(*p_.clearcoat_gloss, si.uv);
  b.diffuse_rate = p_.diffuse_rate;
  b.specular_rate = p_.specular_rate;
  b.clearcoat_rate = p_.clearcoat_rate;
  b.sample_visible = p_.sample_visible;
  b.Prepare();
  return BSDF(si.shading, b, two_sided_);
}

BSDF PhongMaterial::GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const {
  PhongBxDF b;
  b.kd = Reflectance(*diffuse_, si, lambda);
  b.ks = Reflectance(*specular_, si, lambda);
  b.exponent = exponent_;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    if (const float sum = b.kd[i] + b.ks[i]; sum > 1) {
      b.kd[i] /= sum;
      b.ks[i] /= sum;
    }
  }
  return BSDF(si.shading, b, two_sided_);
}

}  // namespace objektiv
