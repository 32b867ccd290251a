// The principled BSDF's evaluation and sampling (the model: scene/principled_bxdf.h).
#include "scene/principled_bxdf.h"

#include <algorithm>
#include <cmath>

#include "base/sampling.h"
#include "scene/fresnel.h"

namespace objektiv {

namespace principled {

float Gtr1D(float alpha, const Vec3f& m) {
  const float a2 = alpha * alpha, c2 = m.z * m.z;
  const float d = (a2 - 1) / (kPi * std::log(a2) * (1 + (a2 - 1) * c2));
  return d * m.z > 1e-20f ? d : 0.f;
}

Vec3f Gtr1Sample(float alpha, Vec2f u) {
  const float a2 = alpha * alpha, phi = 2 * kPi * u.x;
  const float cos2 = (1 - std::pow(a2, 1 - u.y)) / (1 - a2);
  const float cos_t = std::sqrt(std::max(0.f, cos2)), sin_t = std::sqrt(std::max(0.f, 1 - cos2));
  return Vec3f(std::cos(phi) * sin_t, std::sin(phi) * sin_t, cos_t);
}

float SmithGgx1(const Vec3f& w, const Vec3f& m, float alpha) {
  if (Dot(w, m) * w.z <= 0) return 0;
  const float c2 = w.z * w.z;
  if (c2 >= 1) return 1;
  const float tan2 = (1 - c2) / c2;
  return 2 / (1 + std::sqrt(1 + alpha * alpha * tan2));
}

float DisneyDiffuse(const Vec3f& wo, const Vec3f& wi, float roughness) {
  const float Fo = SchlickWeight(std::abs(wo.z)), Fi = SchlickWeight(std::abs(wi.z));
  const Vec3f sum = wo + wi;
  const float cos_d = LengthSquared(sum) > 0 ? Dot(Normalize(sum), wi) : 0.f;
  const float rr = 2 * roughness * cos_d * cos_d;
  return (1 - 0.5f * Fi) * (1 - 0.5f * Fo) + rr * (Fo + Fi + Fo * Fi * (rr - 1));
}

float SheenWeight(const Vec3f& wo, const Vec3f& wi) {
  const Vec3f sum = wo + wi;
  return LengthSquared(sum) > 0 ? SchlickWeight(Dot(Normalize(sum), wi)) : 1.f;
}

}  // namespace principled

using principled::SchlickWeight;

void PrincipledBxDF::Prepare() {
  const float r2 = roughness * roughness, aspect = std::sqrt(1 - 0.9f * anisotropic);
  ax_ = std::max(0.001f, r2 / aspect);
  ay_ = std::max(0.001f, r2 * aspect);
  distrib_ = TrowbridgeReitz(ax_, ay_);
}

int PrincipledBxDF::Flags() const {
  const float brdf = (1 - metallic) * (1 - spec_trans);
  return kReflection | kGlossy | (brdf > 0 ? kDiffuse : 0) | (Transmits() ? kTransmission : 0);
}

PrincipledBxDF::LobeProbabilities PrincipledBxDF::Probabilities(bool front) const {
  if (!front) return {};
  const float pd = (1 - metallic) * (1 - spec_trans) * diffuse_rate, pc = 0.25f * clearcoat * clearcoat_rate,
              ps = specular_rate, total = pd + pc + ps;
  if (!(total > 0)) return {};
  return {pd / total, pc / total, ps / total};
}

float PrincipledBxDF::ProjectedAlpha(const Vec3f& w) const {
  const float s2 = w.x * w.x + w.y * w.y;
  if (s2 <= 0) return std::sqrt(ax_ * ay_);
  return std::sqrt((w.x * w.x * ax_ * ax_ + w.y * w.y * ay_ * ay_) / s2);
}

float PrincipledBxDF::ClearcoatPass(float mu) const {
  return clearcoat > 0 ? 1 - 0.25f * clearcoat * PrincipledTables::ClearcoatAlbedo(mu, clearcoat_gloss) : 1.f;
}

SampledSpectrum PrincipledBxDF::SpecularPass(const Vec3f& w) const {
  const float mu = std::abs(w.z), alpha = ProjectedAlpha(w);
  const float diel = tables->DielectricAlbedo(mu, alpha);
  if (spec_tint <= 0) return SampledSpectrum(1 - diel);
  const float scale = tables->SchlickScale(mu, alpha), bias = tables->SchlickBias(mu, alpha);
  const float r0 = Sqr((Eta() - 1) / (Eta() + 1));
  SampledSpectrum t;
  for (int i = 0; i < kSpectrumSamples; ++i)
    t[i] = 1 - ((1 - spec_tint) * diel + spec_tint * (tint[i] * r0 * scale + bias));
  return t;
}

SampledSpectrum PrincipledBxDF::PlasticFresnel(float c, float f_diel) const {
  if (spec_tint <= 0) return SampledSpectrum(f_diel);
  const float r0 = Sqr((Eta() - 1) / (Eta() + 1)), w = SchlickWeight(std::abs(c));
  SampledSpectrum F;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    const float f0 = tint[i] * r0;
    F[i] = (1 - spec_tint) * f_diel + spec_tint * (f0 + (1 - f0) * w);
  }
  return F;
}

float PrincipledBxDF::SpecularNormalPdf(const Vec3f& wo, const Vec3f& m) const {
  return sample_visible ? distrib_.PdfVisible(wo, m) : distrib_.PdfVisible(Vec3f(0, 0, 1), m);
}

SampledSpectrum PrincipledBxDF::DiffusePart(const Vec3f& wo, const Vec3f& wi) const {
  const float brdf = (1 - metallic) * (1 - spec_trans);
  if (wo.z <= 0 || wi.z <= 0 || brdf <= 0) return {};
  SampledSpectrum d = base * (principled::DisneyDiffuse(wo, wi, roughness) * kInvPi);
  if (sheen > 0) {
    const float fh = principled::SheenWeight(wo, wi);
    for (int i = 0; i < kSpectrumSamples; ++i) d[i] += sheen * (1 + sheen_tint * (tint[i] - 1)) * fh;
  }
  const float scale = PrincipledTables::DiffuseScale(wo.z, roughness, sheen) *
                      PrincipledTables::DiffuseScale(wi.z, roughness, sheen);
  return d * SpecularPass(wo) * SpecularPass(wi) * (brdf * ClearcoatPass(wo.z) * ClearcoatPass(wi.z) * scale);
}

PrincipledBxDF::Evaluation PrincipledBxDF::Evaluate(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const {
  const float cos_o = wo.z, cos_i = wi.z;
  if (cos_o == 0 || cos_i == 0) return {};
  const bool front = cos_o > 0, reflect = cos_o * cos_i > 0;
  const float bsdf = (1 - metallic) * spec_trans, eta = Eta();
  if (!front && bsdf <= 0) return {};
  // The half vector (generalised for refraction), facing +z; both directions must see its front.
  const float etap = reflect ? 1.f : (front ? eta : 1 / eta);
  Vec3f m = wi * etap + wo;
  if (LengthSquared(m) == 0) return {};
  m = FaceForward(Normalize(m), Vec3f(0, 0, 1));
  if (Dot(m, wi) * cos_i <= 0 || Dot(m, wo) * cos_o <= 0) return {};
  const LobeProbabilities p = Probabilities(front);
  const float f_diel = FresnelDielectric(Dot(wo, m), eta);
  // Reflection or refraction at m, as the specular lobe chooses it.
  const float p_refract = front ? bsdf * (1 - f_diel) : 1 - f_diel, p_reflect = 1 - p_refract;
  const float D = distrib_.D(m), G = distrib_.G(wo, wi), pm = SpecularNormalPdf(wo, m);
  Evaluation e;
  if (reflect) {
    const float c = Dot(wo, m);
    SampledSpectrum F;
    if (front) {
      F = PlasticFresnel(c, f_diel) * (1 - metallic);
      for (int i = 0; i < kSpectrumSamples; ++i) F[i] += metallic * (base[i] + (1 - base[i]) * SchlickWeight(c));
    } else {
      F = SampledSpectrum(bsdf * f_diel);
    }
    e.f = F * (D * G / std::abs(4 * cos_o * cos_i));
    e.pdf = p.specular * pm / (4 * std::abs(c)) * p_reflect;
    if (front) {
      const float pass = ClearcoatPass(cos_o) * ClearcoatPass(cos_i);
      e.f = e.f * pass;
      if (clearcoat > 0) {
        const float alpha = principled::ClearcoatAlpha(clearcoat_gloss);
        const float Fcc = 0.04f + 0.96f * SchlickWeight(c);
        const float Gcc = principled::SmithGgx1(wo, m, 0.25f) * principled::SmithGgx1(wi, m, 0.25f);
        const float Dcc = principled::Gtr1D(alpha, m);
        e.f += SampledSpectrum(0.25f * clearcoat * Fcc * Dcc * Gcc / (4 * cos_o * cos_i));
        e.pdf += p.clearcoat * Dcc * m.z / (4 * c);
      }
      e.f += DiffusePart(wo, wi);
      e.pdf += p.diffuse * CosineHemispherePdf(cos_i);
    }
    return e;
  }
  if (bsdf <= 0 || p_refract <= 0) return {};
  const float denom = Sqr(Dot(wi, m) + Dot(wo, m) / etap);
  float ft = bsdf * D * G * std::abs(Dot(wi, m) * Dot(wo, m) / (cos_i * cos_o * denom));
  if (mode == TransportMode::kRadiance) ft /= Sqr(etap);
  // What the outside side does not reflect: the tinted F_p from outside, F_diel from inside.
  const SampledSpectrum pass =
      front ? (SampledSpectrum(1.f) - PlasticFresnel(Dot(wo, m), f_diel)) * ClearcoatPass(cos_o)
            : SampledSpectrum((1 - f_diel) * ClearcoatPass(std::abs(cos_i)));
  e.f = pass * ft;
  for (int i = 0; i < kSpectrumSamples; ++i) e.f[i] *= std::sqrt(std::max(0.f, base[i]));
  e.pdf = p.specular * pm * std::abs(Dot(wi, m)) / denom * p_refract;
  return e;
}

std::optional<BSDFSample> PrincipledBxDF::Sample(const Vec3f& wo, float uc, Vec2f u, TransportMode mode) const {
  if (wo.z == 0) return std::nullopt;
  const bool front = wo.z > 0;
  if (!front && !Transmits()) return std::nullopt;
  const LobeProbabilities p = Probabilities(front);
  Vec3f wi;
  int flags = kReflection | kGlossy;
  float etap = 1;
  if (uc < p.diffuse) {
    wi = SampleCosineHemisphere(u);
    flags = kReflection | kDiffuse;
  } else if (uc < p.diffuse + p.clearcoat) {
    const Vec3f m = principled::Gtr1Sample(principled::ClearcoatAlpha(clearcoat_gloss), u);
    wi = Reflect(wo, m);
  } else {
    // The remaining share of uc, rescaled to [0, 1), chooses reflection or refraction.
    const float uc2 = std::min((uc - p.diffuse - p.clearcoat) / p.specular, 0x1.fffffep-1f);
    const Vec3f m = sample_visible ? distrib_.SampleVisible(wo, u) : distrib_.SampleVisible(Vec3f(0, 0, 1), u);
    if (Dot(wo, m) * wo.z <= 0) return std::nullopt;  // a facet wo sees from behind (D cos sampling)
    const float f_diel = FresnelDielectric(Dot(wo, m), Eta());
    const float p_refract = front ? (1 - metallic) * spec_trans * (1 - f_diel) : 1 - f_diel;
    if (uc2 < p_refract) {
      if (!Refract(wo, m, Eta(), &etap, &wi)) return std::nullopt;
      flags = kTransmission | kGlossy;
    } else {
      wi = Reflect(wo, m);
    }
  }
  if (wi.z == 0 || (wi.z * wo.z > 0) != !(flags & kTransmission)) return std::nullopt;
  const Evaluation e = Evaluate(wo, wi, mode);
  if (e.pdf <= 0) return std::nullopt;
  return BSDFSample{e.f, wi, e.pdf, flags, etap};
}

}  // namespace objektiv
