#include "scene/bsdf.h"

namespace objektiv {

namespace {
template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;
}  // namespace

SampledSpectrum BSDF::f(const Vec3f& wo_world, const Vec3f& wi_world, TransportMode mode) const {
  Vec3f wo = frame_.ToLocal(wo_world), wi = frame_.ToLocal(wi_world);
  if (wo.z == 0 || !SidesAgree(wo_world, wo.z) || !SidesAgree(wi_world, wi.z)) return {};
  if (mix_) return MixF(wo_world, wi_world, mode);
  if (two_sided_ && wo.z < 0 && IsOpaque()) {
    wo.z = -wo.z;
    wi.z = -wi.z;
  }
  return std::visit(Overloaded{[&](const DielectricBxDF& b) { return b.f(wo, wi, mode); },
                               [&](const PrincipledBxDF& b) { return b.f(wo, wi, mode); },
                               [&](const auto& b) { return b.f(wo, wi); }},
                    bxdf_);
}

std::optional<BSDFSample> BSDF::Sample(const Vec3f& wo_world, float uc, Vec2f u, TransportMode mode) const {
  Vec3f wo = frame_.ToLocal(wo_world);
  if (!SidesAgree(wo_world, wo.z)) return std::nullopt;
  if (mix_) {
    std::optional<BSDFSample> s = wo.z == 0 ? std::nullopt : MixSample(wo_world, uc, u, mode);
    if (s && (s->pdf == 0 || s->f.IsBlack() || !SidesAgree(s->wi, Dot(s->wi, frame_.n)))) s.reset();
    return s;
  }
  bool flipped = two_sided_ && wo.z < 0 && IsOpaque();
  if (flipped) wo.z = -wo.z;
  // One returned name on every path, so that the sample is built in the caller's slot (a
  // copy of it stalled on store forwarding).
  std::optional<BSDFSample> s =
      wo.z == 0 ? std::nullopt
                : std::visit(Overloaded{[&](const DielectricBxDF& b) { return b.Sample(wo, uc, u, mode); },
                                        [&](const PrincipledBxDF& b) { return b.Sample(wo, uc, u, mode); },
                                        [&](const auto& b) { return b.Sample(wo, uc, u); }},
                             bxdf_);
  if (s && (s->pdf == 0 || s->f.IsBlack() || s->wi.z == 0)) s.reset();
  if (s) {
    if (flipped) s->wi.z = -s->wi.z;
    const float wi_z = s->wi.z;
    s->wi = frame_.FromLocal(s->wi);
    if (!SidesAgree(s->wi, wi_z)) s.reset();
  }
  return s;
}

float BSDF::Pdf(const Vec3f& wo_world, const Vec3f& wi_world, TransportMode mode) const {
  Vec3f wo = frame_.ToLocal(wo_world), wi = frame_.ToLocal(wi_world);
  if (wo.z == 0 || !SidesAgree(wo_world, wo.z) || !SidesAgree(wi_world, wi.z)) return 0;
  if (mix_) return MixEval(wo_world, wi_world, mode).pdf;
  if (two_sided_ && wo.z < 0 && IsOpaque()) {
    wo.z = -wo.z;
    wi.z = -wi.z;
  }
  return std::visit(Overloaded{[&](const DielectricBxDF& b) { return b.Pdf(wo, wi, mode); },
                               [&](const PrincipledBxDF& b) { return b.Pdf(wo, wi, mode); },
                               [&](const auto& b) { return b.Pdf(wo, wi); }},
                    bxdf_);
}

BSDF::Evaluation BSDF::EvalWithPdf(const Vec3f& wo_world, const Vec3f& wi_world, TransportMode mode) const {
  Vec3f wo = frame_.ToLocal(wo_world), wi = frame_.ToLocal(wi_world);
  if (wo.z == 0 || !SidesAgree(wo_world, wo.z) || !SidesAgree(wi_world, wi.z)) return {};
  if (mix_) return MixEval(wo_world, wi_world, mode);
  if (two_sided_ && wo.z < 0 && IsOpaque()) {
    wo.z = -wo.z;
    wi.z = -wi.z;
  }
  return std::visit(Overloaded{[&](const DielectricBxDF& b) { return Evaluation{b.f(wo, wi, mode), b.Pdf(wo, wi, mode)}; },
                               [&](const PrincipledBxDF& b) {
                                 const PrincipledBxDF::Evaluation e = b.Evaluate(wo, wi, mode);
                                 return Evaluation{e.f, e.pdf};
                               },
                               [&](const auto& b) { return Evaluation{b.f(wo, wi), b.Pdf(wo, wi)}; }},
                    bxdf_);
}

int BSDF::Flags() const {
  if (mix_) return MixFlags();
  return std::visit([](const auto& b) { return b.Flags(); }, bxdf_);
}

}  // namespace objektiv
