// Internal to the scene loader: what the per-kind builders share, and each kind's plugin
// registry (defined in the kind's load_*.cpp).
#pragma once
#include <map>
#include <set>

#include "camera/stereo_camera.h"
#include "io/plugin_registry.h"
#include "io/scene_loader.h"

namespace objektiv {

struct LoaderContext {
  Scene& scene;
  const GlassCatalog& glasses;  // where glass names are looked up
  // Objects referenced more than once (by id) are built once.
  std::map<const ObjectNode*, std::shared_ptr<const Material>> materials;
  std::map<std::pair<const ObjectNode*, int>, std::shared_ptr<const SpectrumTexture>> textures;
  std::map<const ObjectNode*, int> shape_groups;  // built <shape type="shapegroup">s
  std::map<const ObjectNode*, const Medium*> media;
  std::set<const ObjectNode*> attached_media;  // media a shape or the sensor uses
};

// Throws "LOC: WHAT at (x, y, z) lies beyond the scene's coordinate limit" (kMaxSceneCoordinate).
void CheckWithinSceneLimit(const Vec3f& p, const Location& loc, const char* what);
// v scaled to unit length (by its largest component first, so that no square overflows);
// throws naming WHAT if v is zero or not finite.
Vec3f UnitVector(const Vec3f& v, const Location& loc, const char* what);

// Resolves a file name relative to the scene file that mentions it.
std::string ResolvePath(const Location& loc, const std::string& filename);
// The one nested object with this tag, or nullptr; more than one is an error.
const ObjectNode* OneChild(const Properties& p, const std::string& tag);

Spectrum MakeSpectrum(const SpectrumValue& v, SpectrumUsage usage);
// A spectral parameter given as a value (float, rgb, spectrum) or a nested/ref texture.
std::shared_ptr<const SpectrumTexture> GetTexture(const Properties& props, const std::string& name, SpectrumUsage usage,
                                                  float fallback, LoaderContext& ctx);
std::shared_ptr<const SpectrumTexture> BuildTexture(const ObjectNode& node, SpectrumUsage usage, LoaderContext& ctx);

std::shared_ptr<const Material> BuildMaterial(const ObjectNode& node, LoaderContext& ctx);
// Adds a shape to the scene (group < 0) or to a shape group; returns the shape group it
// makes (a shapegroup, built once however often referenced), else -1.
int BuildShape(const ObjectNode& node, LoaderContext& ctx, int group = -1);
std::unique_ptr<Light> BuildEmitter(const ObjectNode& node, LoaderContext& ctx);
// The camera, film settings and sampler settings from a <sensor> (and the medium it sits in).
void BuildSensor(const ObjectNode& node, LoaderContext& ctx, RenderSetup& setup);
// A <medium>, built once however often referenced (load_media.cpp).
const Medium* BuildMedium(const ObjectNode& node, LoaderContext& ctx);
// The medium property `name` of a shape or sensor (nullptr if absent), marked attached; an
// error if it is not a <medium>.
const Medium* MediumProperty(const Properties& p, const std::string& name, LoaderContext& ctx);
// The film (with its reconstruction filter) and the sampler; the defaults without a node.
FilmSettings BuildFilm(const ObjectNode* node);
SamplerSettings BuildSamplerSettings(const ObjectNode* node);
// The path tracer (Mitsuba's default) without a node.
std::unique_ptr<Integrator> BuildIntegrator(const ObjectNode* node, const Scene& scene);

// What every sensor type is built from besides its own properties.
struct SensorBase {
  Transform to_world;
  int width, height;
  float far_clip;
  const GlassCatalog* glasses;  // for a lens file's glass names
  StereoEye eye = {};           // an eye of a stereo rig: where the plugin puts it (none: offset 0)
};

// What an emitter plugin makes: a light of its own, or (type "area") the emission of the
// shape it is nested in.
struct Emission {
  std::unique_ptr<Light> light;
  std::shared_ptr<const SpectrumTexture> area_radiance;
  bool two_sided = false;
};

// The registries, one per kind of object.
using SensorRegistry = PluginRegistry<std::unique_ptr<Camera>, const SensorBase&>;
using FilmRegistry = PluginRegistry<FilmSettings>;
using FilterRegistry = PluginRegistry<std::shared_ptr<const Filter>>;
// A sampler plugin makes the kind of its numbers and the pattern of its film positions.
struct SamplerType {
  SamplerKind kind;
  PixelPattern pattern = PixelPattern::kSampler;
};
using SamplerRegistry = PluginRegistry<SamplerType>;
using IntegratorRegistry = PluginRegistry<std::unique_ptr<Integrator>, const Scene&>;
using ShapeRegistry = PluginRegistry<int, LoaderContext&, int>;  // as BuildShape
using MaterialRegistry = PluginRegistry<std::shared_ptr<Material>, LoaderContext&>;
using TextureRegistry = PluginRegistry<std::shared_ptr<const SpectrumTexture>, SpectrumUsage, LoaderContext&>;
using EmitterRegistry = PluginRegistry<Emission, LoaderContext&>;
using MediumRegistry = PluginRegistry<std::shared_ptr<const Medium>, LoaderContext&>;
using PhaseRegistry = PluginRegistry<HGPhaseFunction>;

const SensorRegistry& SensorPlugins();
const FilmRegistry& FilmPlugins();
const FilterRegistry& FilterPlugins();
const SamplerRegistry& SamplerPlugins();
const IntegratorRegistry& IntegratorPlugins();
const ShapeRegistry& ShapePlugins();
const MaterialRegistry& MaterialPlugins();
const TextureRegistry& TexturePlugins();
const EmitterRegistry& EmitterPlugins();
const MediumRegistry& MediumPlugins();
const PhaseRegistry& PhasePlugins();

// <sensor type="realistic">: a camera with a real lens prescription (load_lens_sensor.cpp).
SensorRegistry::PluginType RealisticSensorPlugin();
// <sensor type="stereo">: two eyes of the nested sensor (load_stereo_sensor.cpp).
SensorRegistry::PluginType StereoSensorPlugin();

}  // namespace objektiv
