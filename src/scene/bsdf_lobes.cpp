// The delta lobes of each BxDF, listed rather than sampled, and the diffuse reflectance that an
// ambient term multiplies: what a Whitted-style tracer asks of a surface.
#include "base/sampling.h"
#include "scene/bsdf.h"
#include "scene/fresnel.h"

namespace objektiv {

namespace {

int Lobes(const DielectricBxDF& b, const Vec3f& wo, TransportMode mode, SpecularLobe out[2]) {
  if (!(b.eta == 1 || b.distrib.EffectivelySmooth())) return 0;
  const float R = b.eta == 1 ? 0.f : FresnelDielectric(wo.z, b.eta), T = 1 - R;
  int n = 0;
  if (R > 0) out[n++] = {Vec3f(-wo.x, -wo.y, wo.z), b.reflect_scale * R, false};
  Vec3f wi;
  float etap;
  if (T > 0 && Refract(wo, Vec3f(0, 0, 1), b.eta, &etap, &wi) && wi.z != 0) {
    SampledSpectrum t = b.transmit_scale * T;
    if (mode == TransportMode::kRadiance) t = t / Sqr(etap);
    out[n++] = {wi, t, true};
  }
  return n;
}

int Lobes(const ThinDielectricBxDF& b, const Vec3f& wo, SpecularLobe out[2]) {
  const SampledSpectrum R = b.Reflectance(AbsCosTheta(wo));
  out[0] = {Vec3f(-wo.x, -wo.y, wo.z), b.reflect_scale * R, false};
  out[1] = {-wo, b.transmit_scale * (SampledSpectrum(1.f) - R), true};
  return 2;
}

int Lobes(const ConductorBxDF& b, const Vec3f& wo, SpecularLobe out[2]) {
  if (!b.distrib.EffectivelySmooth()) return 0;
  out[0] = {Vec3f(-wo.x, -wo.y, wo.z), b.scale * FresnelComplex(AbsCosTheta(wo), b.eta, b.k), false};
  return 1;
}

int Lobes(const PlasticBxDF& b, const Vec3f& wo, SpecularLobe out[2]) {
  if (wo.z <= 0) return 0;
  out[0] = {Vec3f(-wo.x, -wo.y, wo.z), b.specular * FresnelDielectric(wo.z, b.eta), false};
  return 1;
}

}  // namespace

int BSDF::SpecularLobes(const Vec3f& wo_world, SpecularLobe out[kMaxSpecularLobes], TransportMode mode) const {
  Vec3f wo = frame_.ToLocal(wo_world);
  if (wo.z == 0 || !SidesAgree(wo_world, wo.z)) return 0;
  if (mix_) return MixSpecularLobes(wo_world, out, mode);
  const bool flipped = two_sided_ && wo.z < 0 && IsOpaque();
  if (flipped) wo.z = -wo.z;
  int n = 0;
  if (const auto* d = std::get_if<DielectricBxDF>(&bxdf_)) n = Lobes(*d, wo, mode, out);
  if (const auto* t = std::get_if<ThinDielectricBxDF>(&bxdf_)) n = Lobes(*t, wo, out);
  if (const auto* c = std::get_if<ConductorBxDF>(&bxdf_)) n = Lobes(*c, wo, out);
  if (const auto* p = std::get_if<PlasticBxDF>(&bxdf_)) n = Lobes(*p, wo, out);
  int kept = 0;  // those on the sides a bump map allows (RequireSameSide)
  for (int i = 0; i < n; ++i) {
    if (flipped) out[i].wi.z = -out[i].wi.z;
    const float wi_z = out[i].wi.z;
    out[i].wi = frame_.FromLocal(out[i].wi);
    if (SidesAgree(out[i].wi, wi_z)) out[kept++] = out[i];
  }
  return kept;
}

SampledSpectrum BSDF::DiffuseReflectance(const Vec3f& wo_world) const {
  Vec3f wo = frame_.ToLocal(wo_world);
  if (!SidesAgree(wo_world, wo.z)) return {};
  if (mix_) return MixDiffuseReflectance(wo_world);
  if (two_sided_ && wo.z < 0 && IsOpaque()) wo.z = -wo.z;
  if (wo.z <= 0) return {};
  if (const auto* d = std::get_if<DiffuseBxDF>(&bxdf_)) return d->R;
  if (const auto* p = std::get_if<PhongBxDF>(&bxdf_)) return p->kd;
  if (const auto* p = std::get_if<PlasticBxDF>(&bxdf_)) return p->f(wo, Vec3f(0, 0, 1)) * kPi;
  if (const auto* p = std::get_if<RoughPlasticBxDF>(&bxdf_)) return p->DiffusePart(wo, Vec3f(0, 0, 1)) * kPi;
  if (const auto* p = std::get_if<PrincipledBxDF>(&bxdf_)) return p->DiffusePart(wo, Vec3f(0, 0, 1)) * kPi;
  return {};
}

}  // namespace objektiv
