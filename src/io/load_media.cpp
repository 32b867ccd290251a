// The <medium> plugins (participating media) and the <phase> plugins of their phase functions.
#include <algorithm>
#include <cmath>
#include <limits>

#include <spdlog/spdlog.h>

#include "io/loader_context.h"

namespace objektiv {
namespace {

// Properties check that every value is finite and not negative; an albedo must also be at most 1,
// and a coefficient times the medium's scale must stay within single precision.
void CheckCoefficients(const Properties& p, const std::string& name, const SpectrumValue& v, bool albedo,
                       double scale) {
  std::vector<float> values;
  switch (v.kind) {
    case SpectrumValue::Kind::kConstant:
      values = {v.value};
      break;
    case SpectrumValue::Kind::kRgb:
      values = {v.rgb.x, v.rgb.y, v.rgb.z};
      break;
    case SpectrumValue::Kind::kSampled:
      values = v.values;
      break;
    default:  // blackbody, D65, A: emission spectra make no sense as coefficients
      throw ErrorAt(p.LocOf(name), "homogeneous: {} must be a float, an <rgb> or a sampled <spectrum>", name);
  }
  for (float x : values) {
    if (!std::isfinite(x) || x < 0)
      throw ErrorAt(p.LocOf(name), "homogeneous: {} must be finite and not negative, got {}", name, x);
    if (albedo && x > 1) throw ErrorAt(p.LocOf(name), "homogeneous: albedo must lie in [0, 1], got {}", x);
    if (!albedo && !(double(x) * scale <= std::numeric_limits<float>::max()))
      throw ErrorAt(p.LocOf(name), "homogeneous: {} times scale ({} x {}) is not finite", name, x, scale);
  }
}

Spectrum Coefficient(const Properties& p, const std::string& name, float fallback, bool albedo, double scale) {
  const std::optional<SpectrumValue> v = p.SpectrumProp(name);
  if (!v) return Spectrum(fallback);
  CheckCoefficients(p, name, *v, albedo, scale);
  return MakeSpectrum(*v, albedo ? SpectrumUsage::kAlbedo : SpectrumUsage::kUnbounded);
}

// Mitsuba 3's `homogeneous`: sigma_t (default 1) and albedo (default 0.75), or (an Objektiv
// alternative) sigma_a and sigma_s; all times scale; a nested <phase> (isotropic by default).
std::shared_ptr<const Medium> MakeHomogeneous(const Properties& p, LoaderContext&) {
  const bool coefficients = p.Has("sigma_a") || p.Has("sigma_s");
  if (coefficients && (p.Has("sigma_t") || p.Has("albedo")))
    throw ErrorAt(p.LocOf(p.Has("sigma_t") ? "sigma_t" : "albedo"),
                  "homogeneous: give sigma_t and albedo, or sigma_a and sigma_s, not both");
  const double scale = p.Float("scale", 1);
  if (!std::isfinite(scale) || scale < 0)
    throw ErrorAt(p.LocOf("scale"), "homogeneous: scale must be finite and not negative, got {}", scale);
  HGPhaseFunction phase;
  const ObjectNode* phase_node = OneChild(p, "phase");
  if (phase_node) phase = PhasePlugins().Build(*phase_node);
  const bool sample_emitters = p.Bool("sample_emitters", true);
  std::shared_ptr<Medium> medium =
      coefficients ? std::make_shared<Medium>(Medium::FromCoefficients(Coefficient(p, "sigma_a", 0, false, scale),
                                                                       Coefficient(p, "sigma_s", 0, false, scale),
                                                                       float(scale), phase, sample_emitters))
                   : std::make_shared<Medium>(Medium::FromExtinction(Coefficient(p, "sigma_t", 1, false, scale),
                                                                     Coefficient(p, "albedo", 0.75f, true, scale),
                                                                     float(scale), phase, sample_emitters));
  // What only a scattering medium uses, given to one that never scatters.
  auto warn_unused = [](const Location& at, const char* what) {
    spdlog::warn("{}:{}: homogeneous: this medium only absorbs (it scatters nowhere), so its {} changes nothing",
                 at.file, at.line, what);
  };
  if (!medium->Scatters() && phase_node) warn_unused(phase_node->loc, "<phase>");
  if (!medium->Scatters() && p.Has("sample_emitters")) warn_unused(p.LocOf("sample_emitters"), "'sample_emitters'");
  return medium;
}

HGPhaseFunction MakeHenyeyGreenstein(const Properties& p) {
  const double g = p.Float("g", 0.8);
  if (!(g > -1 && g < 1)) throw ErrorAt(p.LocOf("g"), "hg: g must lie strictly between -1 and 1, got {}", g);
  return HGPhaseFunction(float(g));
}

}  // namespace

const MediumRegistry& MediumPlugins() {
  static const MediumRegistry registry("medium", {},
                                       {
                                           {"homogeneous",
                                            {{"sigma_t", PropType::kSpectrum},
                                             {"albedo", PropType::kSpectrum},
                                             {"sigma_a", PropType::kSpectrum},
                                             {"sigma_s", PropType::kSpectrum},
                                             {"scale", PropType::kFloat},
                                             {"sample_emitters", PropType::kBoolean},
                                             {"phase", PropType::kObject}},
                                            MakeHomogeneous},
                                       });
  return registry;
}

const PhaseRegistry& PhasePlugins() {
  static const PhaseRegistry registry(
      "phase", {},
      {
          {"isotropic", {}, [](const Properties&) { return HGPhaseFunction(0); }},
          {"hg", {{"g", PropType::kFloat}}, MakeHenyeyGreenstein},
      });
  return registry;
}

const Medium* BuildMedium(const ObjectNode& node, LoaderContext& ctx) {
  if (auto it = ctx.media.find(&node); it != ctx.media.end()) return it->second;
  const Medium* medium = ctx.scene.AddMedium(MediumPlugins().Build(node, ctx));
  ctx.media[&node] = medium;
  return medium;
}

const Medium* MediumProperty(const Properties& p, const std::string& name, LoaderContext& ctx) {
  if (!p.Has(name)) return nullptr;
  std::shared_ptr<ObjectNode> node = p.TypeOf(name) == ValueType::kObject ? p.Object(name) : nullptr;
  if (!node || node->tag != "medium")
    throw ErrorAt(p.LocOf(name), "'{}' must be a <medium> (nested, or a <ref> to one)", name);
  ctx.attached_media.insert(node.get());
  return BuildMedium(*node, ctx);
}

}  // namespace objektiv
