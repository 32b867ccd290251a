// Ghosts and diffraction: the cost of the flare pieces the live viewer and the renderer need.
// BM_Ghosts: every two-reflection ghost of the double Gauss (45) at f/2.8 for a distant point
// 10 degrees off the axis, at one wavelength, splatted onto a 640 x 480 film, for bundle grids
// of 16 (preview) and 64 rays per side; BM_DiffractionPsf: the stop's pattern, 256^2 pixels,
// one wavelength and white light (31 wavelengths). BM_FlareLayer: the ghost layer of a render
// (render/lens_flare.h) for one point light 12 degrees off the axis, the double Gauss at f/2.8
// with six blades, 1280 x 720, all 45 ghosts (no culling), on every core; its counters give
// the layer's relative difference from a finer one (grid 128, 32 wavelengths, made once: about
// 80 s on 2 cores) where that one is brighter than 1% of its maximum. (This lens's ghosts
// change little with the wavelength: 8 bands give what 32 do, to 1e-4.) BM_GhostPreview: the
// same light's ghosts at preview quality (FlareSettings::Preview) at 640 x 480, as the live
// viewer composes them, against a fine layer, for the lens bare (/0) and coated `multi` (/1;
// its reference takes a few minutes: the coatings' stacks at 32 wavelengths); its counters dx
// and dy: the ghosts' chromaticity minus the fine layer's. BM_DiffractionPass: the diffraction layer's
// kernel and convolution at 1280 x 720.
#include <benchmark/benchmark.h>

#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>

#include "camera/realistic_camera.h"
#include "io/lens_psf.h"
#include "io/scene_loader.h"
#include "render/diffraction_glare.h"
#include "render/lens_flare.h"
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

// A point light 12 degrees right of the view axis, 10 m away, seen by the double Gauss.
RenderSetup FlareScene(int width = 1280, int height = 720, const std::string& coating = "") {
  std::string xml = R"(<scene version="3.0.0">
  <sensor type="realistic">
    <string name="lens" value="dgauss.50mm"/><float name="fnumber" value="2.8"/><integer name="blades" value="6"/>COATING
    <boolean name="ghosts" value="true"/><float name="ghost_cull" value="0"/>
    <transform name="to_world"><lookat origin="0, 0, 0" target="0, 0, -1" up="0, 1, 0"/></transform>
    <film type="hdrfilm"><integer name="width" value="WIDTH"/><integer name="height" value="HEIGHT"/></film>
  </sensor>
  <emitter type="point"><point name="position" x="2.07" y="0.5" z="-9.78"/><rgb name="intensity" value="1"/></emitter>
</scene>)";
  xml.replace(xml.find("WIDTH"), 5, std::to_string(width));
  xml.replace(xml.find("HEIGHT"), 6, std::to_string(height));
  xml.replace(xml.find("COATING"), 7, coating.empty() ? "" : R"(<string name="coating" value=")" + coating + R"("/>)");
  return LoadSceneFromString(xml, "flare.xml", {});
}

void BM_FlareLayer(benchmark::State& state) {
  spdlog::set_level(spdlog::level::warn);
  const RenderSetup setup = FlareScene();
  const auto& camera = dynamic_cast<const RealisticCamera&>(*setup.camera);
  const CropWindow crop = setup.film.crop;
  FlareSettings settings;
  settings.ghosts = true;
  settings.cull = 0;
  settings.grid = int(state.range(0));
  settings.wavelengths = int(state.range(1));
  FlareImages f;
  for (auto _ : state) {
    f = RenderFlare(*setup.scene, camera, crop, settings);
    benchmark::DoNotOptimize(f.ghosts.data());
  }
  // Against a finer layer (made once): relative difference of Y where the finer one exceeds
  // 1% of its peak.
  static const FlareImages r = [&] {
    FlareSettings fine = settings;
    fine.grid = 128;
    fine.wavelengths = 32;
    return RenderFlare(*setup.scene, camera, crop, fine);
  }();
  double peak = 0;
  for (size_t i = 1; i < r.ghosts.size(); i += 3) peak = std::max<double>(peak, r.ghosts[i]);
  std::vector<double> diffs;
  for (size_t i = 1; i < r.ghosts.size(); i += 3)
    if (r.ghosts[i] > 0.01 * peak) diffs.push_back(std::abs(f.ghosts[i] - r.ghosts[i]) / r.ghosts[i]);
  std::sort(diffs.begin(), diffs.end());
  double below = 0;
  for (double d : diffs) below += d < 0.01;
  state.counters["pixels_compared"] = double(diffs.size());
  state.counters["share_within_1pct"] = diffs.empty() ? 0 : below / diffs.size();
  state.counters["median_rel_diff"] = diffs.empty() ? 0 : diffs[diffs.size() / 2];
  state.counters["p95_rel_diff"] = diffs.empty() ? 0 : diffs[diffs.size() * 95 / 100];
  state.SetLabel(fmt::format("one point light, dgauss f/2.8, {} ghosts, grid {}, {} wavelengths, 1280x720, all cores",
                             f.ghosts_traced, settings.grid, settings.wavelengths));
}
BENCHMARK(BM_FlareLayer)->Args({16, 8})->Args({32, 16})->Args({64, 16})->Args({64, 8})->Args({80, 8})->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

// The ghosts of one point light at preview quality (FlareSettings::Preview) at 640 x 480, on
// every core: what the live viewer composes while the camera moves. Counters as
// BM_FlareLayer's, against the same finer layer at 640 x 480.
void BM_GhostPreview(benchmark::State& state) {
  spdlog::set_level(spdlog::level::warn);
  // Argument 0: the lens as it ships (bare); 1: coated `multi`.
  const std::string coating = state.range(0) ? "multi" : "";
  const RenderSetup setup = FlareScene(640, 480, coating);
  const auto& camera = dynamic_cast<const RealisticCamera&>(*setup.camera);
  const CropWindow crop = setup.film.crop;
  FlareSettings settings = FlareSettings::Preview();
  settings.ghosts = true;
  FlareImages f;
  for (auto _ : state) {
    f = RenderFlare(*setup.scene, camera, crop, settings);
    benchmark::DoNotOptimize(f.ghosts.data());
  }
  static std::map<std::string, FlareImages> references;
  if (!references.count(coating)) {
    FlareSettings fine;
    fine.ghosts = true, fine.cull = 0, fine.grid = 128, fine.wavelengths = 32;
    references[coating] = RenderFlare(*setup.scene, camera, crop, fine);
  }
  const FlareImages& r = references[coating];
  double peak = 0, sum_r = 0, sum_f = 0;
  std::array<double, 3> xyz_r{}, xyz_f{};
  for (size_t i = 1; i < r.ghosts.size(); i += 3) peak = std::max<double>(peak, r.ghosts[i]);
  std::vector<double> diffs;
  for (size_t i = 1; i < r.ghosts.size(); i += 3) {
    sum_r += r.ghosts[i], sum_f += f.ghosts[i];
    for (int c = 0; c < 3; ++c) xyz_r[size_t(c)] += r.ghosts[i - 1 + size_t(c)], xyz_f[size_t(c)] += f.ghosts[i - 1 + size_t(c)];
    if (r.ghosts[i] > 0.01 * peak) diffs.push_back(std::abs(f.ghosts[i] - r.ghosts[i]) / r.ghosts[i]);
  }
  std::sort(diffs.begin(), diffs.end());
  state.counters["median_rel_diff"] = diffs.empty() ? 0 : diffs[diffs.size() / 2];
  state.counters["p95_rel_diff"] = diffs.empty() ? 0 : diffs[diffs.size() * 95 / 100];
  state.counters["total_Y_ratio"] = sum_r > 0 ? sum_f / sum_r : 0;
  // The ghosts' colour: chromaticity x and y of their whole light, the preview's minus the
  // finer layer's.
  auto chromaticity = [](const std::array<double, 3>& c) {
    const double s = c[0] + c[1] + c[2];
    return s > 0 ? std::array<double, 2>{c[0] / s, c[1] / s} : std::array<double, 2>{0, 0};
  };
  state.counters["dx"] = chromaticity(xyz_f)[0] - chromaticity(xyz_r)[0];
  state.counters["dy"] = chromaticity(xyz_f)[1] - chromaticity(xyz_r)[1];
  state.SetLabel(fmt::format("one point light, dgauss{} f/2.8, {} ghosts ({} culled), grid {}, {} wavelengths, 640x480, all cores",
                             coating.empty() ? "" : " coated " + coating, f.ghosts_traced, f.ghosts_culled, settings.grid, settings.wavelengths));
}
BENCHMARK(BM_GhostPreview)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_DiffractionPass(benchmark::State& state) {
  const StopShape iris = StopShape::Iris(6, 0, 0);
  const PupilFunction pupil = [&](double u, double v) { return iris.Contains(u, v) ? 1.0 : 0.0; };
  std::vector<float> image(size_t(1280) * 720 * 3, 0.f);
  image[(size_t(360) * 1280 + 640) * 3 + 1] = 1;
  int radius = 0;
  for (auto _ : state) {
    const DiffractionKernel k = MakeDiffractionKernel(pupil, 8, 28.125, 28.125, 1469, 16);
    std::vector<float> copy = image;
    ApplyDiffraction(copy, 1280, 720, k);
    radius = k.radius;
    benchmark::DoNotOptimize(copy.data());
  }
  state.SetLabel(fmt::format("6 blades, f/8, 16 wavelengths, 1280x720 (28 um pixels), kernel radius {}", radius));
}
BENCHMARK(BM_DiffractionPass)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace objektiv
