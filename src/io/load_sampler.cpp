// The <sampler> plugins: each names a sampler kind; all read the count and the seed.
#include "base/log.h"
#include "io/loader_context.h"

namespace objektiv {

const SamplerRegistry& SamplerPlugins() {
  static const SamplerRegistry registry(
      "sampler", {{"sample_count", PropType::kInteger}, {"seed", PropType::kInteger}, {"jitter", PropType::kBoolean}},
      {
          {"independent", {}, [](const Properties&) { return SamplerKind::kIndependent; }},
          {"stratified", {}, [](const Properties&) { return SamplerKind::kStratified; }, {"multijitter", "orthogonal"}},
          {"sobol", {}, [](const Properties&) { return SamplerKind::kSobol; }, {"ldsampler"}},
      });
  return registry;
}

SamplerSettings BuildSamplerSettings(const ObjectNode* node) {
  SamplerSettings s;
  if (!node) return s;
  const SamplerRegistry& registry = SamplerPlugins();
  const SamplerRegistry::PluginType& plugin = registry.Find(*node);
  Properties p = registry.Open(*node, plugin);
  s.kind = plugin.make(p);
  s.spp = int(p.IntIn("sample_count", 4, 1, 1 << 24));
  s.seed = uint64_t(p.IntIn("seed", 0, 0, INT64_MAX));
  if (!p.Bool("jitter", true))  // stratified/multijitter: always jittered here
    spdlog::warn("{}:{}: sampler: jitter = false is not supported; samples are jittered", p.LocOf("jitter").file,
                 p.LocOf("jitter").line);
  p.WarnUnused();
  return s;
}

}  // namespace objektiv
