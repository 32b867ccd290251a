// Blinn-Phong with the exact normalisation of its half-vector lobe.
//
// With D(h) = cos^n(theta_h), the reflected fraction at normal incidence is
// int cos^n(theta_i / 2) cos(theta_i) dw_i = 8 pi (2^(-n/2) + n) / ((n+2)(n+4)), so scaling the
// lobe by the inverse gives directional albedo ks there; away from the normal part of the lobe
// falls below the horizon and the albedo only drops (test_bsdf.cpp checks both). The lobe is
// sampled through its half vector: cos(theta_h) = u^(1/(n+1)) has density
// (n+1)/(2 pi) cos^n(theta_h) per solid angle of h, and (4 |wo.h|)^-1 turns that into wi's.
#include <cmath>

#include "base/sampling.h"
#include "scene/bxdf.h"

namespace objektiv {

namespace {

float LobeNormalisation(float n) { return (n + 2) * (n + 4) / (8 * kPi * (std::exp2(-n / 2) + n)); }

}  // namespace

int PhongBxDF::Flags() const {
  int flags = 0;
  if (!kd.IsBlack()) flags |= kReflection | kDiffuse;
  if (!ks.IsBlack()) flags |= kReflection | kGlossy;
  return flags;
}

float PhongBxDF::SpecularProbability() const {
  const float d = kd.Average(), s = ks.Average();
  return d + s > 0 ? s / (d + s) : 0;
}

// f and the sampling density together: the half vector and its power once.
PhongBxDF::Evaluation PhongBxDF::Evaluate(const Vec3f& wo, const Vec3f& wi) const {
  if (wo.z <= 0 || wi.z <= 0) return {};
  const float ps = SpecularProbability();
  Evaluation e{kd * kInvPi, (1 - ps) * CosineHemispherePdf(wi.z)};
  const Vec3f h = Normalize(wo + wi);
  if (ps > 0 && h.z > 0) {
    const float lobe = std::pow(h.z, exponent);
    e.f += ks * (LobeNormalisation(exponent) * lobe);
    e.pdf += ps * (exponent + 1) * 0.5f * kInvPi * lobe / (4 * Dot(wo, h));
  }
  return e;
}

SampledSpectrum PhongBxDF::f(const Vec3f& wo, const Vec3f& wi) const { return Evaluate(wo, wi).f; }

float PhongBxDF::Pdf(const Vec3f& wo, const Vec3f& wi) const { return Evaluate(wo, wi).pdf; }

std::optional<BSDFSample> PhongBxDF::Sample(const Vec3f& wo, float uc, Vec2f u) const {
  if (wo.z <= 0) return std::nullopt;
  Vec3f wi;
  const bool glossy = uc < SpecularProbability();
  if (glossy) {
    const float cos_h = std::pow(u.x, 1 / (exponent + 1));
    const float sin_h = std::sqrt(std::max(0.f, 1 - cos_h * cos_h)), phi = 2 * kPi * u.y;
    const Vec3f h(sin_h * std::cos(phi), sin_h * std::sin(phi), cos_h);
    wi = Reflect(wo, h);
  } else {
    wi = SampleCosineHemisphere(u);
  }
  if (wi.z <= 0) return std::nullopt;
  const Evaluation e = Evaluate(wo, wi);
  if (e.pdf == 0) return std::nullopt;
  return BSDFSample{e.f, wi, e.pdf, kReflection | (glossy ? kGlossy : kDiffuse)};
}

}  // namespace objektiv
