// Builds everything a render needs from a scene file.
#pragma once
#include <map>
#include <memory>
#include <string>

#include "camera/camera.h"
#include "io/tonemap.h"
#include "io/xml_document.h"
#include "render/film.h"
#include "render/integrator.h"

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
  std::string type = "independent";
  int spp = 4;
  uint64_t seed = 0;
};

struct RenderSetup {
  std::unique_ptr<Scene> scene;
  std::unique_ptr<Camera> camera;
  std::unique_ptr<Integrator> integrator;
  FilmSettings film;
  SamplerSettings sampler;
};

// Throws InputError ("file:line: message") for any problem in the scene or its files.
RenderSetup LoadScene(const std::string& path, const std::map<std::string, std::string>& defines);
RenderSetup LoadSceneFromString(const std::string& xml, const std::string& name,
                                const std::map<std::string, std::string>& defines);

std::unique_ptr<Sampler> MakeSampler(const SamplerSettings& s);

}  // namespace objektiv
