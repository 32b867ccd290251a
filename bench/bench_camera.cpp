// The realistic camera: camera rays per second through each shipped lens (rejected rays
// counted too, as the renderer makes them: batches of 64 samples of one pixel), and the
// camera's setup time (loading the lens, focusing, pupil bounds).
#include <benchmark/benchmark.h>

#include <spdlog/spdlog.h>

#include "base/rng.h"
#include "camera/lens_camera_setup.h"
#include "optics/lens_file.h"

namespace objektiv {
namespace {

const char* const kLenses[] = {"dgauss.50mm", "wide.22mm", "fisheye.10mm", "telephoto.250mm", "tessar.brendel.100mm"};

std::unique_ptr<Camera> MakeCamera(const char* lens, double fnumber) {
  LensCameraSpec spec;
  spec.lens = LoadLens(lens);
  spec.fnumber = fnumber;
  spec.focus_distance = 5;
  return MakeLensCamera(Transform(), 768, 512, spec);
}

void BM_CameraRays(benchmark::State& state) {
  const char* lens = kLenses[state.range(0)];
  spdlog::set_level(spdlog::level::warn);
  // The f-number (0: wide open), or wide open for the lenses that do not open that far.
  const double fnumber = std::max(state.range(1) / 10.0, WideOpenFNumber(LoadLens(lens)));
  auto cam = MakeCamera(lens, fnumber);
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
  state.SetLabel(fmt::format("{} f/{:.3g}", lens, fnumber));
}
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

}  // namespace
}  // namespace objektiv
