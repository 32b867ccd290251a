// The <integrator> plugins: each makes an Integrator from its properties.
#include "io/loader_context.h"

namespace objektiv {

const IntegratorRegistry& IntegratorPlugins() {
  static const IntegratorRegistry registry(
      "integrator", {},
      {
          {"path",
           {{"max_depth", PropType::kInteger}, {"rr_depth", PropType::kInteger}},
           [](const Properties& p, const Scene& scene) -> std::unique_ptr<Integrator> {
             int max_depth = int(p.IntIn("max_depth", -1, -1, 1 << 20));
             if (max_depth == 0) throw ErrorAt(p.LocOf("max_depth"), "max_depth must be -1 (unbounded) or at least 1");
             return std::make_unique<PathIntegrator>(scene, max_depth, int(p.IntIn("rr_depth", 5, 1, 1 << 20)));
           }},
          {"direct",
           {{"shading_samples", PropType::kInteger},
            {"emitter_samples", PropType::kInteger},
            {"bsdf_samples", PropType::kInteger}},
           [](const Properties& p, const Scene& scene) -> std::unique_ptr<Integrator> {
             int shading = int(p.IntIn("shading_samples", 1, 0, 1 << 16));
             return std::make_unique<DirectIntegrator>(scene, int(p.IntIn("emitter_samples", shading, 0, 1 << 16)),
                                                       int(p.IntIn("bsdf_samples", shading, 0, 1 << 16)));
           }},
      });
  return registry;
}

std::unique_ptr<Integrator> BuildIntegrator(const ObjectNode* node, const Scene& scene) {
  if (!node) return std::make_unique<PathIntegrator>(scene, -1, 5);
  return IntegratorPlugins().Build(*node, scene);
}

}  // namespace objektiv
