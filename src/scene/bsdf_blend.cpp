// A blend of two BSDFs (Mitsuba's blendbsdf): f = (1 - w) f_a + w f_b, sampled by choosing a
// part with probability 1 - w or w (the lobe choice uc, rescaled, then serves the part) and
// reporting the density of the whole mixture, (1 - w) pdf_a + w pdf_b, for a glossy or
// diffuse direction. A delta direction of one part is reported with that part's weight on
// both f and the density: only that part has a delta there (with probability one), and its
// share of the estimate is f / pdf as it is.
//
// Each part shades with its own frame; the integrators multiply f by |wi . n| of the blend's
// frame, so a part whose normal differs (a bump map inside the blend) has its f scaled by
// |wi . n_part| / |wi . n|.
#include "scene/bsdf.h"

namespace objektiv {

struct BSDF::Mix {
  BSDF part[2];
  float weight[2];  // 1 - w, w
};

BSDF BSDF::Blend(const Frame& shading, BSDF a, BSDF b, float weight) {
  BSDF out;
  out.frame_ = shading;
  out.bxdf_ = DiffuseBxDF{};
  out.mix_ = std::make_shared<const Mix>(Mix{{std::move(a), std::move(b)}, {1 - weight, weight}});
  return out;
}

namespace {

// |wi . n_part| / |wi . n|: what turns the part's f into one the blend's cosine serves.
float CosineRatio(const Frame& part, const Frame& blend, const Vec3f& wi) {
  if (part.n.x == blend.n.x && part.n.y == blend.n.y && part.n.z == blend.n.z) return 1;
  const float c = AbsDot(wi, blend.n);
  return c > 0 ? AbsDot(wi, part.n) / c : 0;
}

}  // namespace

SampledSpectrum BSDF::MixF(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const {
  SampledSpectrum f(0.f);
  for (int k = 0; k < 2; ++k)
    if (mix_->weight[k] > 0)
      f += mix_->part[k].f(wo, wi, mode) * (mix_->weight[k] * CosineRatio(mix_->part[k].frame_, frame_, wi));
  return f;
}

BSDF::Evaluation BSDF::MixEval(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const {
  Evaluation e;
  for (int k = 0; k < 2; ++k) {
    if (mix_->weight[k] <= 0) continue;
    const Evaluation p = mix_->part[k].EvalWithPdf(wo, wi, mode);
    e.f += p.f * (mix_->weight[k] * CosineRatio(mix_->part[k].frame_, frame_, wi));
    e.pdf += mix_->weight[k] * p.pdf;
  }
  return e;
}

std::optional<BSDFSample> BSDF::MixSample(const Vec3f& wo, float uc, Vec2f u, TransportMode mode) const {
  const float wb = mix_->weight[1];
  const int k = uc < wb ? 1 : 0;
  // The rest of uc, uniform again, for the part's own lobe choice.
  const float rest = k == 1 ? uc / wb : (uc - wb) / (1 - wb);
  std::optional<BSDFSample> s = mix_->part[k].Sample(wo, std::min(rest, 0x1.fffffep-1f), u, mode);
  if (!s) return s;
  if (s->IsSpecular()) {
    s->f *= mix_->weight[k] * CosineRatio(mix_->part[k].frame_, frame_, s->wi);
    s->pdf *= mix_->weight[k];
    return s;
  }
  const Evaluation e = MixEval(wo, s->wi, mode);
  s->f = e.f;
  s->pdf = e.pdf;
  return s;
}

int BSDF::MixFlags() const {
  int flags = 0;
  for (int k = 0; k < 2; ++k)
    if (mix_->weight[k] > 0) flags |= mix_->part[k].Flags();
  return flags;
}

int BSDF::MixSpecularLobes(const Vec3f& wo, SpecularLobe out[kMaxSpecularLobes], TransportMode mode) const {
  int n = 0;
  for (int k = 0; k < 2; ++k) {
    if (mix_->weight[k] <= 0) continue;
    SpecularLobe lobes[kMaxSpecularLobes];
    const int m = mix_->part[k].SpecularLobes(wo, lobes, mode);
    // The lobe's weight is f |cos| with the part's own cosine already.
    for (int i = 0; i < m && n < kMaxSpecularLobes; ++i) {
      lobes[i].weight *= mix_->weight[k];
      out[n++] = lobes[i];
    }
  }
  return n;
}

SampledSpectrum BSDF::MixDiffuseReflectance(const Vec3f& wo) const {
  SampledSpectrum r(0.f);
  for (int k = 0; k < 2; ++k)
    if (mix_->weight[k] > 0) r += mix_->part[k].DiffuseReflectance(wo) * mix_->weight[k];
  return r;
}

}  // namespace objektiv
