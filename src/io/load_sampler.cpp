// The <sampler> plugins: each names a sampler kind (or a pixel pattern over Sobol' numbers);
// all read the count, the seed and the adaptive sampling settings.
#include <fmt/format.h>

#include "base/error.h"
#include "base/log.h"
#include "io/loader_context.h"

namespace objektiv {

namespace {
constexpr Named<AdaptiveMode> kAdaptiveModes[] = {
    {"none", AdaptiveMode::kNone}, {"statistical", AdaptiveMode::kStatistical}, {"whitted", AdaptiveMode::kWhitted}};

SamplerType Pattern(PixelPattern p) { return {SamplerKind::kSobol, p}; }
}  // namespace

const SamplerRegistry& SamplerPlugins() {
  static const SamplerRegistry registry(
      "sampler",
      {{"sample_count", PropType::kInteger},
       {"seed", PropType::kInteger},
       {"jitter", PropType::kBoolean},
       {"adaptive", kAdaptiveModes},
       {"adaptive_threshold", PropType::kFloat},
       {"adaptive_min_samples", PropType::kInteger},
       {"adaptive_floor", PropType::kFloat},
       {"adaptive_max_depth", PropType::kInteger}},
      {
          {"independent", {}, [](const Properties&) { return SamplerType{SamplerKind::kIndependent}; }},
          {"stratified", {}, [](const Properties&) { return SamplerType{SamplerKind::kStratified}; },
           {"multijitter", "orthogonal"}},
          {"sobol", {}, [](const Properties&) { return SamplerType{SamplerKind::kSobol}; }, {"ldsampler"}},
          {"grid", {}, [](const Properties&) { return Pattern(PixelPattern::kGrid); }},
          {"rgss", {}, [](const Properties&) { return Pattern(PixelPattern::kRgss); }},
          {"quincunx", {}, [](const Properties&) { return Pattern(PixelPattern::kQuincunx); }},
      });
  return registry;
}

SamplerSettings BuildSamplerSettings(const ObjectNode* node) {
  SamplerSettings s;
  if (!node) return s;
  const SamplerRegistry& registry = SamplerPlugins();
  const SamplerRegistry::PluginType& plugin = registry.Find(*node);
  Properties p = registry.Open(*node, plugin);
  const SamplerType type = plugin.make(p);
  s.kind = type.kind;
  s.pattern = type.pattern;
  s.spp = int(p.IntIn("sample_count", 4, 1, 1 << 24));
  s.spp_given = p.Has("sample_count");
  s.seed = uint64_t(p.IntIn("seed", 0, 0, INT64_MAX));
  if (!p.Bool("jitter", true))  // stratified/multijitter: always jittered here
    spdlog::warn("{}:{}: sampler: jitter = false is not supported; samples are jittered", p.LocOf("jitter").file,
                 p.LocOf("jitter").line);
  AdaptiveSettings& a = s.adaptive;
  a.mode = p.Choice("adaptive", AdaptiveMode::kNone, kAdaptiveModes);
  const bool statistical = a.mode == AdaptiveMode::kStatistical, whitted = a.mode == AdaptiveMode::kWhitted;
  a.threshold = p.FloatIn("adaptive_threshold", AdaptiveSettings::DefaultThreshold(a.mode), 1e-6, 1e6);
  a.min_samples = int(p.IntIn("adaptive_min_samples", 16, 2, 1 << 24));
  a.floor = p.FloatIn("adaptive_floor", 0.01, 0, 1e30);
  a.max_depth = int(p.IntIn("adaptive_max_depth", 2, 0, 4));
  // What the mode does not read is said, not ignored.
  auto unused = [&](const char* name, const char* why) {
    if (p.Has(name))
      spdlog::warn("{}:{}: sampler: {} does not apply {}", p.LocOf(name).file, p.LocOf(name).line, name, why);
  };
  const char* mode_why = a.mode == AdaptiveMode::kNone ? "without adaptive sampling" : "to adaptive = whitted";
  if (!statistical) unused("adaptive_min_samples", mode_why);
  if (!whitted) unused("adaptive_max_depth", a.mode == AdaptiveMode::kNone ? mode_why : "to adaptive = statistical");
  if (a.mode == AdaptiveMode::kNone) {
    unused("adaptive_threshold", mode_why);
    unused("adaptive_floor", mode_why);
  }
  if (whitted) {
    if (s.pattern != PixelPattern::kSampler)
      throw InputError(fmt::format("{}:{}: sampler: adaptive = whitted places its own samples (corners and centres of "
                                   "the pixel's squares); it cannot take the {} pattern: use a sobol, stratified or "
                                   "independent sampler", p.loc().file, p.loc().line, PixelPatternName(s.pattern)));
    unused("sample_count",
           "to adaptive = whitted: a pixel takes 5 to (2^adaptive_max_depth+1)^2 + 4^adaptive_max_depth samples as "
           "its contrast asks (41 at depth 2)");
  }
  CheckSamplerSettings(s, fmt::format("{}:{}", p.loc().file, p.loc().line));
  p.WarnUnused();
  return s;
}

std::string DescribeSampling(const SamplerSettings& s) {
  std::string text;
  if (s.pattern != PixelPattern::kSampler) text = fmt::format("pattern {}", PixelPatternName(s.pattern));
  const AdaptiveSettings& a = s.adaptive;
  if (a.mode == AdaptiveMode::kStatistical)
    text += fmt::format("{}adaptive statistical, threshold {}, min {}, floor {}", text.empty() ? "" : "; ", a.threshold,
                        a.min_samples, a.floor);
  else if (a.mode == AdaptiveMode::kWhitted)
    text += fmt::format("{}adaptive whitted, threshold {}, depth {}, floor {}", text.empty() ? "" : "; ", a.threshold,
                        a.max_depth, a.floor);
  return text;
}

void CheckSamplerSettings(const SamplerSettings& s, const std::string& where) {
  const AdaptiveSettings& a = s.adaptive;
  if (a.mode == AdaptiveMode::kStatistical && a.min_samples >= s.spp)
    spdlog::warn("{}: sampler: adaptive_min_samples {} is not below the {} samples per pixel: every pixel takes them all "
                 "(no adaptive sampling)", where, a.min_samples, s.spp);
  if (s.pattern != PixelPattern::kSampler && a.mode != AdaptiveMode::kStatistical) {
    const int round = PatternRoundSize(s.pattern, s.spp);
    const bool whole = s.pattern == PixelPattern::kQuincunx ? s.spp >= 5 && (s.spp - 5) % 2 == 0 : s.spp % round == 0;
    if (!whole)
      spdlog::warn("{}: sampler: {} samples per pixel are not whole rounds of the {} pattern ({}{}): the last round is "
                   "partial", where, s.spp, PixelPatternName(s.pattern), round,
                   s.pattern == PixelPattern::kQuincunx ? ", then 2 a round" : "");
  }
}

}  // namespace objektiv
