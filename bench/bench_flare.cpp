// Ghosts and diffraction: the cost of the flare pieces the live viewer and the renderer need.
// BM_Ghosts: every two-reflection ghost of the double Gauss (45) at f/2.8 for a distant point
// 10 degrees off the axis, at one wavelength, splatted onto a 640 x 480 film, for bundle grids
// of 16 (preview) and 64 rays per side; BM_DiffractionPsf: the stop's pattern, 256^2 pixels,
// one wavelength and white light (31 wavelengths).
#include <benchmark/benchmark.h>

#include <spdlog/spdlog.h>

#include <cmath>

#include "io/lens_psf.h"
#include "optics/ghosts.h"
#include "optics/lens_file.h"
#include "optics/lens_setup.h"

namespace objektiv {
namespace {

void BM_Ghosts(benchmark::State& state) {
  spdlog::set_level(spdlog::level::warn);
  const LensSystem lens = SetUpLens(LoadLens("dgauss.50mm", GlassCatalog::Default()), {2.8, 0, {}},
                                    {INFINITY, FocusRequest::From::kFilm, false})
                              .lens;
  const PointSource source = PointSource::Distant({-std::sin(0.17), 0, std::cos(0.17)});
  const std::vector<Ghost> ghosts = TwoReflectionGhosts(lens);
  const FilmRaster raster{640, 480, -18, -13.5, 36.0 / 640, 27.0 / 480};
  std::vector<float> image(640 * 480);
  const int grid = int(state.range(0));
  for (auto _ : state) {
    std::fill(image.begin(), image.end(), 0.f);
    for (const Ghost& g : ghosts) Splat(GhostBundle(lens, g, source, 550, grid), raster, 1, image.data());
    benchmark::DoNotOptimize(image.data());
  }
  state.SetLabel(fmt::format("dgauss f/2.8, {} ghosts, grid {}, one wavelength, 640x480, one thread", ghosts.size(), grid));
}
BENCHMARK(BM_Ghosts)->Arg(16)->Arg(64)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_DiffractionPsf(benchmark::State& state) {
  const StopShape iris = StopShape::Iris(6, 0, 0);
  const PupilFunction pupil = [&](double u, double v) { return iris.Contains(u, v) ? 1.0 : 0.0; };
  const bool white = state.range(0) == 1;
  for (auto _ : state)
    benchmark::DoNotOptimize(DiffractionImage(pupil, 8, white ? std::nullopt : std::optional<double>(550), 1.1, 256));
  state.SetLabel(white ? "6 blades, f/8, 256^2, white light" : "6 blades, f/8, 256^2, 550 nm");
}
BENCHMARK(BM_DiffractionPsf)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace objektiv
