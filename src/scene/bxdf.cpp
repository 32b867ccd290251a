#include "scene/bxdf.h"

#include "base/sampling.h"
#include "scene/fresnel.h"

namespace objektiv {

// --- Diffuse ------------------------------------------------------------------------

SampledSpectrum DiffuseBxDF::f(const Vec3f& wo, const Vec3f& wi) const {
  if (wo.z <= 0 || wi.z <= 0) return {};
  return R * kInvPi;
}

std::optional<BSDFSample> DiffuseBxDF::Sample(const Vec3f& wo, float, Vec2f u) const {
  if (wo.z <= 0) return std::nullopt;
  Vec3f wi = SampleCosineHemisphere(u);
  if (wi.z <= 0) return std::nullopt;
  return BSDFSample{R * kInvPi, wi, CosineHemispherePdf(wi.z), kReflection | kDiffuse};
}

float DiffuseBxDF::Pdf(const Vec3f& wo, const Vec3f& wi) const {
  if (wo.z <= 0 || wi.z <= 0) return 0;
  return CosineHemispherePdf(wi.z);
}

// --- Dielectric ---------------------------------------------------------------------

int DielectricBxDF::Flags() const {
  int flags = (eta == 1) ? kTransmission : (kReflection | kTransmission);
  return flags | (distrib.EffectivelySmooth() ? kSpecular : kGlossy);
}

namespace {

// The half vector of a rough dielectric pair (wo, wi), facing +z; false if degenerate or
// if either direction sees the back of the microfacet.
bool DielectricHalfVector(const Vec3f& wo, const Vec3f& wi, float eta, Vec3f* wm, float* etap) {
  float cos_o = wo.z, cos_i = wi.z;
  bool reflect = cos_i * cos_o > 0;
  *etap = reflect ? 1.f : (cos_o > 0 ? eta : 1 / eta);
  Vec3f m = wi * *etap + wo;
  if (cos_i == 0 || cos_o == 0 || LengthSquared(m) == 0) return false;
  m = FaceForward(Normalize(m), Vec3f(0, 0, 1));
  if (Dot(m, wi) * cos_i < 0 || Dot(m, wo) * cos_o < 0) return false;
  *wm = m;
  return true;
}

}  // namespace

SampledSpectrum DielectricBxDF::f(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const {
  if (eta == 1 || distrib.EffectivelySmooth()) return {};
  Vec3f wm;
  float etap;
  if (!DielectricHalfVector(wo, wi, eta, &wm, &etap)) return {};
  float F = FresnelDielectric(Dot(wo, wm), eta);
  if (wo.z * wi.z > 0)
    return reflect_scale * (distrib.D(wm) * distrib.G(wo, wi) * F / std::abs(4 * wi.z * wo.z));
  float denom = Sqr(Dot(wi, wm) + Dot(wo, wm) / etap) * wi.z * wo.z;
  float ft = distrib.D(wm) * (1 - F) * distrib.G(wo, wi) * std::abs(Dot(wi, wm) * Dot(wo, wm) / denom);
  if (mode == TransportMode::kRadiance) ft /= Sqr(etap);
  return transmit_scale * ft;
}

float DielectricBxDF::Pdf(const Vec3f& wo, const Vec3f& wi, TransportMode) const {
  if (eta == 1 || distrib.EffectivelySmooth()) return 0;
  Vec3f wm;
  float etap;
  if (!DielectricHalfVector(wo, wi, eta, &wm, &etap)) return 0;
  float R = FresnelDielectric(Dot(wo, wm), eta), T = 1 - R;
  if (wo.z * wi.z > 0) return distrib.PdfVisible(wo, wm) / (4 * AbsDot(wo, wm)) * R / (R + T);
  float denom = Sqr(Dot(wi, wm) + Dot(wo, wm) / etap);
  return distrib.PdfVisible(wo, wm) * AbsDot(wi, wm) / denom * T / (R + T);
}

std::optional<BSDFSample> DielectricBxDF::Sample(const Vec3f& wo, float uc, Vec2f u, TransportMode mode) const {
  if (eta == 1 || distrib.EffectivelySmooth()) {
    float R = FresnelDielectric(wo.z, eta), T = 1 - R;
    if (uc < R / (R + T)) {
      Vec3f wi(-wo.x, -wo.y, wo.z);
      return BSDFSample{reflect_scale * (R / AbsCosTheta(wi)), wi, R / (R + T), kReflection | kSpecular};
    }
    Vec3f wi;
    float etap;
    if (!Refract(wo, Vec3f(0, 0, 1), eta, &etap, &wi) || wi.z == 0) return std::nullopt;
    SampledSpectrum ft = transmit_scale * (T / AbsCosTheta(wi));
    if (mode == TransportMode::kRadiance) ft = ft / Sqr(etap);
    return BSDFSample{ft, wi, T / (R + T), kTransmission | kSpecular, etap};
  }
  Vec3f wm = distrib.SampleVisible(wo, u);
  float R = FresnelDielectric(Dot(wo, wm), eta), T = 1 - R;
  if (uc < R / (R + T)) {
    Vec3f wi = Reflect(wo, wm);
    if (!SameHemisphere(wo, wi)) return std::nullopt;
    float pdf = distrib.PdfVisible(wo, wm) / (4 * AbsDot(wo, wm)) * R / (R + T);
    SampledSpectrum f = reflect_scale * (distrib.D(wm) * distrib.G(wo, wi) * R / std::abs(4 * wi.z * wo.z));
    return BSDFSample{f, wi, pdf, kReflection | kGlossy};
  }
  Vec3f wi;
  float etap;
  if (!Refract(wo, wm, eta, &etap, &wi) || SameHemisphere(wo, wi) || wi.z == 0) return std::nullopt;
  float denom = Sqr(Dot(wi, wm) + Dot(wo, wm) / etap);
  float pdf = distrib.PdfVisible(wo, wm) * AbsDot(wi, wm) / denom * T / (R + T);
  float ft = T * distrib.D(wm) * distrib.G(wo, wi) * std::abs(Dot(wi, wm) * Dot(wo, wm) / (wi.z * wo.z * denom));
  if (mode == TransportMode::kRadiance) ft /= Sqr(etap);
  return BSDFSample{transmit_scale * ft, wi, pdf, kTransmission | kGlossy, etap};
}

// --- Conductor ----------------------------------------------------------------------

SampledSpectrum ConductorBxDF::f(const Vec3f& wo, const Vec3f& wi) const {
  if (!SameHemisphere(wo, wi) || distrib.EffectivelySmooth()) return {};
  float cos_o = AbsCosTheta(wo), cos_i = AbsCosTheta(wi);
  if (cos_i == 0 || cos_o == 0) return {};
  Vec3f wm = wi + wo;
  if (LengthSquared(wm) == 0) return {};
  wm = Normalize(wm);
  SampledSpectrum F = FresnelComplex(AbsDot(wo, wm), eta, k);
  return scale * F * (distrib.D(wm) * distrib.G(wo, wi) / (4 * cos_i * cos_o));
}

float ConductorBxDF::Pdf(const Vec3f& wo, const Vec3f& wi) const {
  if (!SameHemisphere(wo, wi) || distrib.EffectivelySmooth()) return 0;
  Vec3f wm = wo + wi;
  if (LengthSquared(wm) == 0) return 0;
  wm = FaceForward(Normalize(wm), Vec3f(0, 0, 1));
  return distrib.PdfVisible(wo, wm) / (4 * AbsDot(wo, wm));
}

std::optional<BSDFSample> ConductorBxDF::Sample(const Vec3f& wo, float, Vec2f u) const {
  if (distrib.EffectivelySmooth()) {
    Vec3f wi(-wo.x, -wo.y, wo.z);
    SampledSpectrum f = scale * FresnelComplex(AbsCosTheta(wi), eta, k) / AbsCosTheta(wi);
    return BSDFSample{f, wi, 1, kReflection | kSpecular};
  }
  if (wo.z == 0) return std::nullopt;
  Vec3f wm = distrib.SampleVisible(wo, u);
  Vec3f wi = Reflect(wo, wm);
  if (!SameHemisphere(wo, wi)) return std::nullopt;
  float pdf = distrib.PdfVisible(wo, wm) / (4 * AbsDot(wo, wm));
  float cos_o = AbsCosTheta(wo), cos_i = AbsCosTheta(wi);
  if (cos_i == 0 || cos_o == 0) return std::nullopt;
  SampledSpectrum F = FresnelComplex(AbsDot(wo, wm), eta, k);
  SampledSpectrum f = scale * F * (distrib.D(wm) * distrib.G(wo, wi) / (4 * cos_i * cos_o));
  return BSDFSample{f, wi, pdf, kReflection | kGlossy};
}

// --- Plastic ------------------------------------------------------------------------

namespace {
float PlasticSpecularProbability(float Fo, float weight) {
  float ps = Fo * weight, pd = (1 - Fo) * (1 - weight);
  return ps + pd > 0 ? ps / (ps + pd) : 0;
}
}  // namespace

SampledSpectrum PlasticBxDF::f(const Vec3f& wo, const Vec3f& wi) const {
  if (wo.z <= 0 || wi.z <= 0) return {};
  float Fo = FresnelDielectric(wo.z, eta), Fi = FresnelDielectric(wi.z, eta);
  // Light refracts into the coat, scatters diffusely, and bounces between the base and the
  // coat's underside (a geometric series in fdr_int) before leaving.
  SampledSpectrum d = diffuse;
  for (int i = 0; i < kSpectrumSamples; ++i)
    d[i] /= 1 - (nonlinear ? d[i] * fdr_int : fdr_int);
  return d * ((1 - Fo) * (1 - Fi) * kInvPi / (eta * eta));
}

float PlasticBxDF::Pdf(const Vec3f& wo, const Vec3f& wi) const {
  if (wo.z <= 0 || wi.z <= 0) return 0;
  float ps = PlasticSpecularProbability(FresnelDielectric(wo.z, eta), specular_sampling_weight);
  return (1 - ps) * CosineHemispherePdf(wi.z);
}

std::optional<BSDFSample> PlasticBxDF::Sample(const Vec3f& wo, float uc, Vec2f u) const {
  if (wo.z <= 0) return std::nullopt;
  float Fo = FresnelDielectric(wo.z, eta);
  float ps = PlasticSpecularProbability(Fo, specular_sampling_weight);
  if (uc < ps) {
    Vec3f wi(-wo.x, -wo.y, wo.z);
    return BSDFSample{specular * (Fo / wi.z), wi, ps, kReflection | kSpecular};
  }
  Vec3f wi = SampleCosineHemisphere(u);
  if (wi.z <= 0) return std::nullopt;
  return BSDFSample{f(wo, wi), wi, (1 - ps) * CosineHemispherePdf(wi.z), kReflection | kDiffuse};
}

}  // namespace objektiv
