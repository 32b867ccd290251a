// The classic tracer as a preview: frames of the spheres on a checkerboard
// (scenes/classic/spheres-checkerboard.xml) at 640 x 480, one sample per pixel, on every core,
// the scene loaded once (as the live viewer renders frame after frame). Arguments: the shadow
// grid (n x n shadow rays per area light and the sky): 4 as shipped, 1 for a scene as POV-Ray
// traces it by default (one shadow ray per light); the wavelength sets (4 as shipped: sixteen
// wavelengths a pixel, no colour noise; 1: four, the colour noise of a spectral sample).
#include <benchmark/benchmark.h>

#include <spdlog/spdlog.h>

#include "io/scene_loader.h"
#include "render/renderer.h"

namespace objektiv {
namespace {

void BM_WhittedFrame(benchmark::State& state) {
  spdlog::set_level(spdlog::level::warn);
  const int grid = int(state.range(0)), sets = int(state.range(1));
  const RenderSetup setup = LoadScene(OBJEKTIV_SCENES_DIR "/classic/spheres-checkerboard.xml",
                                      {{"shadow_grid", std::to_string(grid)}, {"wavelength_sets", std::to_string(sets)}});
  std::unique_ptr<Sampler> sampler = MakeSampler(setup.sampler);
  RenderOptions options;
  options.spp_end = 1;
  uint64_t rays = 0;
  for (auto _ : state) {
    Film film(setup.film.width, setup.film.height, setup.film.crop, setup.film.filter);
    RenderStats stats = Render(*setup.camera, *setup.integrator, *sampler, film, options);
    rays += stats.rays;
    benchmark::DoNotOptimize(film);
  }
  state.counters["Mrays/s"] = benchmark::Counter(double(rays) * 1e-6, benchmark::Counter::kIsRate);
  state.counters["fps"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
  state.SetLabel(fmt::format("whitted, 640x480, 1 spp, shadow grid {}x{}, {} wavelength sets", grid, grid, sets));
}
BENCHMARK(BM_WhittedFrame)
    ->Args({4, 4})
    ->Args({1, 4})
    ->Args({4, 1})
    ->Args({1, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace objektiv
