// Rough plastic: the coat's microfacet reflection plus the base seen through the coat.
//
// The base is sampled by the cosine, the coat by its visible normals; the lobe is chosen with
// probability ps = (1 - T_o) w / ((1 - T_o) w + T_o (1 - w)) (w: the material's specular
// sampling weight, as Mitsuba), and f and the density are always those of the whole mixture.
#include "base/sampling.h"
#include "scene/bxdf.h"
#include "scene/fresnel.h"

namespace objektiv {

float RoughPlasticBxDF::SpecularProbability(float cos_o) const {
  const float t = coat->Transmittance(cos_o);
  const float ps = (1 - t) * specular_sampling_weight, pd = t * (1 - specular_sampling_weight);
  return ps + pd > 0 ? ps / (ps + pd) : 0;
}

SampledSpectrum RoughPlasticBxDF::DiffusePart(const Vec3f& wo, const Vec3f& wi) const {
  if (wo.z <= 0 || wi.z <= 0) return {};
  const float fdr = coat->InternalReflectance(), eta = coat->eta();
  SampledSpectrum d = diffuse;
  for (int i = 0; i < kSpectrumSamples; ++i) d[i] /= 1 - (nonlinear ? d[i] * fdr : fdr);
  return d * (coat->Transmittance(wo.z) * coat->Transmittance(wi.z) * kInvPi / (eta * eta));
}

RoughPlasticBxDF::Evaluation RoughPlasticBxDF::Evaluate(const Vec3f& wo, const Vec3f& wi) const {
  if (wo.z <= 0 || wi.z <= 0) return {};
  const float ps = SpecularProbability(wo.z);
  Evaluation e{DiffusePart(wo, wi), (1 - ps) * CosineHemispherePdf(wi.z)};
  const Vec3f sum = wo + wi;
  if (LengthSquared(sum) == 0) return e;
  const Vec3f wm = Normalize(sum);
  const TrowbridgeReitz& d = coat->distrib();
  const float F = FresnelDielectric(Dot(wo, wm), coat->eta());
  e.f += specular * (F * d.D(wm) * d.G(wo, wi) / (4 * wo.z * wi.z));
  e.pdf += ps * d.PdfVisible(wo, wm) / (4 * Dot(wo, wm));
  return e;
}

SampledSpectrum RoughPlasticBxDF::f(const Vec3f& wo, const Vec3f& wi) const { return Evaluate(wo, wi).f; }

float RoughPlasticBxDF::Pdf(const Vec3f& wo, const Vec3f& wi) const { return Evaluate(wo, wi).pdf; }

std::optional<BSDFSample> RoughPlasticBxDF::Sample(const Vec3f& wo, float uc, Vec2f u) const {
  if (wo.z <= 0) return std::nullopt;
  const bool glossy = uc < SpecularProbability(wo.z);
  const Vec3f wi = glossy ? Reflect(wo, coat->distrib().SampleVisible(wo, u)) : SampleCosineHemisphere(u);
  if (wi.z <= 0) return std::nullopt;
  const Evaluation e = Evaluate(wo, wi);
  if (e.pdf == 0) return std::nullopt;
  return BSDFSample{e.f, wi, e.pdf, kReflection | (glossy ? kGlossy : kDiffuse)};
}

}  // namespace objektiv
