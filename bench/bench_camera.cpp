// The realistic camera: camera rays per second through each shipped lens (rejected rays
// counted too, as the renderer makes them: batches of 64 samples of one pixel), and the
// camera's setup time (loading the lens, focusing, pupil bounds).
#include <benchmark/benchmark.h>

#include <spdlog/spdlog.h>

#include "base/rng.h"
#include "camera/lens_camera_setup.h"
#include "optics/coating_library.h"
#include "optics/lens_file.h"

namespace objektiv {
namespace {

const char* const kLenses[] = {"dgauss.50mm", "wide.22mm", "fisheye.10mm", "telephoto.250mm", "tessar.brendel.100mm"};

std::unique_ptr<Camera> MakeCamera(const char* lens, double fnumber, const char* coating = nullptr) {
  LensCameraSpec spec;
  spec.lens = LoadLens(lens, GlassCatalog::Default());
  if (coating) Recoat(spec.lens, CoatingForLens(coating, spec.lens));
  spec.fnumber = fnumber;
  spec.focus_distance = 5;
  return MakeLensCamera(Transform(), 768, 512, spec);
}

// Camera rays through `lens` at `fnumber`, its air-glass surfaces coated so (null: as the file says).
void TraceCameraRays(benchmark::State& state, const char* lens, double fnumber, const char* coating) {
  spdlog::set_level(spdlog::level::warn);
  // The f-number (0: wide open), or wide open for the lenses that do not open that far.
  fnumber = std::max(fnumber, WideOpenFNumber(LoadLens(lens, GlassCatalog::Default())));
  auto cam = MakeCamera(lens, fnumber, coating);
  PCG32 rng(2, 9);
  const int n = 64;
  std::vector<CameraSample> samples(n);
  std::vector<SampledWavelengths> lambdas(n);
  std::vector<std::optional<CameraRay>> out(n);
  CameraRayCount count;
  for (auto _ : state) {
    state.PauseTiming();
    Vec2f pixel(768 * rng.UniformFloat(), 512 * rng.UniformFloat());
    for (int i = 0; i < n; ++i) {
      samples[i] = {pixel + Vec2f(rng.UniformFloat(), rng.UniformFloat()), Vec2f(rng.UniformFloat(), rng.UniformFloat())};
      lambdas[i] = SampledWavelengths::SampleVisible(rng.UniformFloat());
    }
    state.ResumeTiming();
    cam->GenerateRays(samples, lambdas, out, count);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * n);
  state.counters["pass_rate"] = count.traced ? double(count.passed) / count.traced : 0;
  state.SetLabel(fmt::format("{} f/{:.3g}{}{}", lens, fnumber, coating ? " coating " : "", coating ? coating : ""));
}

// Arguments: the lens, 10 x the f-number.
void BM_CameraRays(benchmark::State& state) { TraceCameraRays(state, kLenses[state.range(0)], state.range(1) / 10.0, nullptr); }

// The coatings' cost: the double Gauss at f/2.8 bare (0), MgF2 (1) and multi-coated (2).
void BM_CameraRaysCoated(benchmark::State& state) {
  const char* const coatings[] = {"none", "MgF2", "multi"};
  TraceCameraRays(state, "dgauss.50mm", 2.8, coatings[state.range(0)]);
}
BENCHMARK(BM_CameraRaysCoated)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CameraRays)->ArgsProduct({{0, 1, 2, 3, 4}, {28, 80}})->Unit(benchmark::kMicrosecond);
// The pass rate at every full stop from wide open to f/16 (the rays per second as above).
BENCHMARK(BM_CameraRays)
    ->Name("BM_CameraPassRate")
    ->ArgsProduct({{0, 1, 2, 3, 4}, {0, 40, 56, 110, 160}})
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(0.1);

void BM_CameraSetup(benchmark::State& state) {
  const char* lens = kLenses[state.range(0)];
  spdlog::set_level(spdlog::level::warn);
  for (auto _ : state) benchmark::DoNotOptimize(MakeCamera(lens, 0));
  state.SetLabel(fmt::format("{} wide open, load + focus + pupil bounds", lens));
}
BENCHMARK(BM_CameraSetup)->DenseRange(0, 4)->Unit(benchmark::kMillisecond)->UseRealTime();

// The same with a stop that is not round, wide open: three straight blades (argument 1 = 0),
// six curved ones (1), and a mask open on its right half (2); the pass rate of its rays.
void BM_CameraSetupNotRound(benchmark::State& state) {
  const char* lens = kLenses[state.range(0)];
  spdlog::set_level(spdlog::level::warn);
  LensCameraSpec spec;
  spec.lens = LoadLens(lens, GlassCatalog::Default());
  spec.focus_distance = 5;
  spec.settings.sensor_width = 36, spec.settings.sensor_height = 24;
  const char* what = "";
  switch (state.range(1)) {
    case 0: spec.blades = 3, spec.blade_rotation = 90, what = "3 straight blades"; break;
    case 1: spec.blades = 6, spec.blade_curvature = 0.5, what = "6 curved blades"; break;
    default: {
      Image half(64, 64, {"R", "G", "B"});
      for (int y = 0; y < 64; ++y)
        for (int x = 32; x < 64; ++x)
          for (int c = 0; c < 3; ++c) half.At(x, y, c) = 1;
      spec.settings.aperture_mask = std::make_shared<ApertureMask>(half);
      what = "half-open mask";
    }
  }
  std::unique_ptr<Camera> cam;
  for (auto _ : state) cam = MakeLensCamera(Transform(), 768, 512, spec);
  PCG32 rng(2, 9);
  std::vector<CameraSample> samples(64);
  std::vector<SampledWavelengths> lambdas(64);
  std::vector<std::optional<CameraRay>> out(64);
  CameraRayCount count;
  uint64_t lit = 0;
  for (int batch = 0; batch < 500; ++batch) {
    for (int i = 0; i < 64; ++i) {
      samples[i] = {Vec2f(768 * rng.UniformFloat(), 512 * rng.UniformFloat()), Vec2f(rng.UniformFloat(), rng.UniformFloat())};
      lambdas[i] = SampledWavelengths::SampleVisible(rng.UniformFloat());
    }
    cam->GenerateRays(samples, lambdas, out, count);
    for (const auto& r : out) lit += r && r->weight[0] > 0;
  }
  state.counters["pass_rate"] = count.traced ? double(lit) / count.traced : 0;
  state.SetLabel(fmt::format("{} wide open, {}", lens, what));
}
BENCHMARK(BM_CameraSetupNotRound)
    ->ArgsProduct({{0, 1, 2, 3, 4}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

}  // namespace
}  // namespace objektiv
