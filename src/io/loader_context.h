// Internal to the scene loader: what the per-kind builders share.
#pragma once
#include <map>

#include "io/properties.h"
#include "io/scene_loader.h"

namespace objektiv {

struct LoaderContext {
  Scene& scene;
  // Objects referenced more than once (by id) are built once.
  std::map<const ObjectNode*, std::shared_ptr<const Material>> materials;
  std::map<std::pair<const ObjectNode*, int>, std::shared_ptr<const SpectrumTexture>> textures;
  std::map<const ObjectNode*, int> shape_groups;  // built <shape type="shapegroup">s
};

// Throws "LOC: WHAT at (x, y, z) lies beyond the scene's coordinate limit" (kMaxSceneCoordinate).
void CheckWithinSceneLimit(const Vec3f& p, const Location& loc, const char* what);
// v scaled to unit length (by its largest component first, so that no square overflows);
// throws naming WHAT if v is zero or not finite.
Vec3f UnitVector(const Vec3f& v, const Location& loc, const char* what);

// Resolves a file name relative to the scene file that mentions it.
std::string ResolvePath(const Location& loc, const std::string& filename);

Spectrum MakeSpectrum(const SpectrumValue& v, SpectrumUsage usage);
// A spectral parameter given as a value (float, rgb, spectrum) or a nested/ref texture.
std::shared_ptr<const SpectrumTexture> GetTexture(const Properties& props, const std::string& name, SpectrumUsage usage,
                                                  float fallback, LoaderContext& ctx);
std::shared_ptr<const SpectrumTexture> BuildTexture(const ObjectNode& node, SpectrumUsage usage, LoaderContext& ctx);

std::shared_ptr<const Material> BuildMaterial(const ObjectNode& node, LoaderContext& ctx);
// Adds a shape to the scene (group < 0) or to a shape group; shapegroup and instance too.
void BuildShape(const ObjectNode& node, LoaderContext& ctx, int group = -1);
std::unique_ptr<Light> BuildEmitter(const ObjectNode& node, LoaderContext& ctx);
// The camera, film settings and sampler settings from a <sensor>.
void BuildSensor(const ObjectNode& node, RenderSetup& setup);
// <sensor type="realistic"> (a lens prescription), called by BuildSensor.
std::unique_ptr<Camera> BuildLensCamera(const Properties& p, const Transform& to_world, int width, int height,
                                        float far_clip);
std::unique_ptr<Integrator> BuildIntegrator(const ObjectNode* node, const Scene& scene);

// "unknown <tag> type 'x' (known: a, b, c)"
template <typename Map>
[[noreturn]] void UnknownType(const ObjectNode& node, const Map& registry) {
  std::string known;
  for (const auto& [name, f] : registry) known += (known.empty() ? "" : ", ") + name;
  throw ErrorAt(node.loc, "unknown {} type '{}' (known: {})", node.tag, node.type, known);
}

}  // namespace objektiv
