// Builds everything a render needs from a scene file.
#pragma once
#include <map>
#include <memory>
#include <string>

#include "camera/camera.h"
#include "io/plugin_registry.h"
#include "io/tonemap.h"
#include "io/xml_document.h"
#include "optics/glass_catalog.h"
#include "render/film.h"
#include "render/integrator.h"
#include "render/sampler.h"

namespace objektiv {

struct FilmSettings {
  Location loc;  // of the <film> (or of the <sensor> without one), for errors about its size
  int width = 768, height = 576;
  CropWindow crop;  // defaults to the full film
  std::shared_ptr<const Filter> filter;
  float exposure = 0;  // stops
  ToneMap tonemap = ToneMap::kClamp;
  const ColorSpace* color_space = &ColorSpace::Rec709();
};

struct SamplerSettings {
  SamplerKind kind = SamplerKind::kIndependent;
  PixelPattern pattern = PixelPattern::kSampler;
  int spp = 4;
  bool spp_given = false;  // the scene's sampler wrote sample_count
  uint64_t seed = 0;
  AdaptiveSettings adaptive;
};
// The sampler's pattern and adaptive settings in words, for headers and checkpoints (a render
// resumed with others is refused): "" for a plain sampler.
std::string DescribeSampling(const SamplerSettings& s);
// Refuses (InputError naming `where`) adaptive settings that cannot hold together, and warns
// of those that do not apply; `spp` the samples per pixel the render will take.
void CheckSamplerSettings(const SamplerSettings& s, const std::string& where);

struct RenderSetup {
  std::unique_ptr<Scene> scene;
  std::unique_ptr<Camera> camera;
  std::unique_ptr<Integrator> integrator;
  FilmSettings film;
  SamplerSettings sampler;
};

// Throws InputError ("file:line: message") for any problem in the scene or its files. Glass
// names (a dielectric's int_ior, a lens file's media) are looked up in `glasses`: the
// command line passes the shipped set, GlassCatalog::Default() (the default here for tests).
RenderSetup LoadScene(const std::string& path, const std::map<std::string, std::string>& defines,
                      const GlassCatalog& glasses = GlassCatalog::Default());
RenderSetup LoadSceneFromString(const std::string& xml, const std::string& name,
                                const std::map<std::string, std::string>& defines,
                                const GlassCatalog& glasses = GlassCatalog::Default());

// What LoadScene does after parsing: the set-up of a parsed scene (the interactive viewer keeps
// the document, to build the camera again with its sensor's properties changed).
RenderSetup BuildScene(const SceneDocument& doc, const GlassCatalog& glasses = GlassCatalog::Default());
// The camera of a <sensor> node (the scene's, or a copy with some properties changed), built
// again at width x height pixels: its film, sampler and medium are not read (BuildScene did).
// Throws InputError naming the property at fault.
std::unique_ptr<Camera> BuildCamera(const ObjectNode& sensor, int width, int height,
                                    const GlassCatalog& glasses = GlassCatalog::Default());

std::unique_ptr<Sampler> MakeSampler(const SamplerSettings& s);

// Every kind of scene object and its plugins, with the properties each reads: what
// docs/scene-format.md documents.
std::vector<PluginKind> ScenePluginKinds();

}  // namespace objektiv
