// A BSDF at a surface point: one BxDF in the shading frame, in world-space directions.
#pragma once
#include <memory>
#include <variant>

#include "base/frame.h"
#include "scene/bxdf.h"
#include "scene/principled_bxdf.h"

namespace objektiv {

using BxDF = std::variant<DiffuseBxDF, DielectricBxDF, ConductorBxDF, PlasticBxDF, PhongBxDF, ThinDielectricBxDF,
                          RoughPlasticBxDF, PrincipledBxDF>;

// The most delta lobes a BSDF has at one wo: a smooth dielectric's two, for each of the (at
// most kMaxBlendLeaves) BSDFs a blend mixes.
constexpr int kMaxBlendLeaves = 4;
constexpr int kMaxSpecularLobes = 2 * kMaxBlendLeaves;

// A delta lobe of a BSDF at wo (scene/bsdf_lobes.cpp): the one direction it sends light to and
// the share it sends (f |cos theta_i| of the lobe: Fresnel reflectance or transmittance with
// the colour scales, and the 1/eta^2 of radiance crossing an interface).
struct SpecularLobe {
  Vec3f wi;
  SampledSpectrum weight;
  bool transmission = false;
};

class BSDF {
 public:
  BSDF() = default;
  // two_sided: opaque BxDFs, which scatter on their front side only (as in Mitsuba), act the
  // same on both sides. Dielectrics are always two-sided.
  BSDF(const Frame& shading, BxDF bxdf, bool two_sided)
      : frame_(shading), bxdf_(std::move(bxdf)), two_sided_(two_sided) {}
  // Mitsuba's blendbsdf: (1 - weight) a + weight b, weight in [0, 1], at one surface point
  // (scene/bsdf_blend.cpp). a and b keep their own frames (either may be bump-mapped); the
  // blend's frame is `shading`, the one the integrators take the cosine with, and each part's
  // f is scaled by its own cosine over that one, so that f |cos| is each part's own.
  static BSDF Blend(const Frame& shading, BSDF a, BSDF b, float weight);

  SampledSpectrum f(const Vec3f& wo_world, const Vec3f& wi_world, TransportMode mode = TransportMode::kRadiance) const;
  std::optional<BSDFSample> Sample(const Vec3f& wo_world, float uc, Vec2f u,
                                   TransportMode mode = TransportMode::kRadiance) const;
  float Pdf(const Vec3f& wo_world, const Vec3f& wi_world, TransportMode mode = TransportMode::kRadiance) const;
  // f and Pdf together (one frame change, one dispatch), for next-event estimation.
  struct Evaluation {
    SampledSpectrum f;
    float pdf = 0;
  };
  Evaluation EvalWithPdf(const Vec3f& wo_world, const Vec3f& wi_world,
                         TransportMode mode = TransportMode::kRadiance) const;
  int Flags() const;
  bool IsSpecular() const { return (Flags() & (kDiffuse | kGlossy)) == 0; }
  // Whether Sample uses its 1D number (to choose between lobes); single-lobe BxDFs do not,
  // so integrators need not draw it.
  bool UsesLobeChoice() const {
    return mix_ || std::holds_alternative<RoughPlasticBxDF>(bxdf_) || std::holds_alternative<DielectricBxDF>(bxdf_) || std::holds_alternative<PlasticBxDF>(bxdf_) ||
           std::holds_alternative<PhongBxDF>(bxdf_) || std::holds_alternative<ThinDielectricBxDF>(bxdf_) || std::holds_alternative<PrincipledBxDF>(bxdf_);
  }
  // Every delta lobe at wo, written to out (at most two for one BxDF: a smooth dielectric's
  // reflection and refraction; a blend's parts' together), for tracers that follow each of
  // them instead of sampling one (whitted).
  int SpecularLobes(const Vec3f& wo_world, SpecularLobe out[kMaxSpecularLobes],
                    TransportMode mode = TransportMode::kRadiance) const;
  // The reflectance of the BSDF's diffuse part seen from wo, the share of a uniform ambient
  // light it returns: Lambert's R, Phong's kd, plastic's and rough plastic's base through
  // their coat (pi f toward the shading normal), principled's diffuse and sheen under its layers, a blend's parts' weighted; zero for the others.
  SampledSpectrum DiffuseReflectance(const Vec3f& wo_world) const;
  const Frame& frame() const { return frame_; }
  // For a perturbed shading frame (bump and normal maps): a direction wo or wi on different
  // sides of the frame's normal and of `n` (the unperturbed shading normal) scatters nothing,
  // so that no light leaks through the surface where the perturbed normal tilts past it (as
  // Mitsuba, which tests wi alone; both keep the BSDF reciprocal).
  void RequireSameSide(const Vec3f& n) {
    side_n_ = n;
    check_side_ = true;
  }

 private:
  struct Mix;
  // The blend's versions of the public calls (scene/bsdf_blend.cpp).
  SampledSpectrum MixF(const Vec3f& wo_world, const Vec3f& wi_world, TransportMode mode) const;
  std::optional<BSDFSample> MixSample(const Vec3f& wo_world, float uc, Vec2f u, TransportMode mode) const;
  Evaluation MixEval(const Vec3f& wo_world, const Vec3f& wi_world, TransportMode mode) const;
  int MixFlags() const;
  int MixSpecularLobes(const Vec3f& wo_world, SpecularLobe out[kMaxSpecularLobes], TransportMode mode) const;
  SampledSpectrum MixDiffuseReflectance(const Vec3f& wo_world) const;
  bool IsOpaque() const {
    if (const auto* p = std::get_if<PrincipledBxDF>(&bxdf_)) return !p->Transmits();
    return !std::holds_alternative<DielectricBxDF>(bxdf_) && !std::holds_alternative<ThinDielectricBxDF>(bxdf_);
  }
  // Whether w (world; w_z its local z) passes the RequireSameSide test.
  bool SidesAgree(const Vec3f& w_world, float w_z) const { return !check_side_ || Dot(w_world, side_n_) * w_z > 0; }
  Frame frame_;
  BxDF bxdf_;
  bool two_sided_ = false;
  bool check_side_ = false;
  Vec3f side_n_;
  std::shared_ptr<const Mix> mix_;  // set for a blend (bxdf_ then unused)
};

}  // namespace objektiv
