// Rendering small scenes from XML strings inside tests.
#pragma once
#include <string>

#include "base/image.h"
#include "io/scene_loader.h"
#include "render/renderer.h"

namespace objektiv::test {

struct RenderResult {
  Image image;
  RenderStats stats;
};

inline RenderResult RenderXml(const std::string& xml, int threads = 0, int tile_size = 16) {
  RenderSetup setup = LoadSceneFromString(xml, "test.xml", {});
  std::unique_ptr<Sampler> sampler = MakeSampler(setup.sampler);
  Film film(setup.film.width, setup.film.height, setup.film.crop, setup.film.filter);
  RenderOptions opt;
  opt.spp_end = sampler->spp();
  opt.threads = threads;
  opt.tile_size = tile_size;
  RenderStats stats = Render(*setup.camera, *setup.integrator, *sampler, film, opt);
  return {film.ToImage(*setup.film.color_space), stats};
}

// Mean and standard error of the mean of one channel over all pixels (pixels are
// independent estimates: every sample lands in exactly one pixel).
struct MeanSe {
  double mean = 0, se = 0;
};
inline MeanSe ChannelMean(const Image& img, int c) {
  double s = 0, s2 = 0;
  int n = img.width * img.height;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      double v = img.At(x, y, c);
      s += v;
      s2 += v * v;
    }
  double mean = s / n, var = std::max(0.0, s2 / n - mean * mean);
  return {mean, std::sqrt(var / (n - 1))};
}

}  // namespace objektiv::test
