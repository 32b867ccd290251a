// Micro-benchmarks: ray casting against the Cornell box (random and camera rays), BSDF sampling, samplers.
// Run: build/objektiv-bench (the full-render figure comes from bench/cornell.sh).
#include <benchmark/benchmark.h>

#include "optics/lens_tracer.h"
#include "base/rng.h"
#include "base/sampling.h"
#include "io/scene_loader.h"
#include "optics/batch_tracer.h"
#include "optics/lens_file.h"
#include "optics/paraxial.h"
#include "render/sampler.h"
#include "scene/bsdf.h"
#include "scene/fresnel.h"

namespace objektiv {
namespace {

const RenderSetup& Cornell() {
  static RenderSetup setup = LoadScene(OBJEKTIV_SCENES_DIR "/cornell-box/cornell-box.xml", {});
  return setup;
}

// Random rays from points inside the box in uniform directions (incoherent, like bounces).
std::vector<Ray> CornellRays(int n) {
  PCG32 rng(1, 1);
  std::vector<Ray> rays(n);
  for (Ray& r : rays) {
    r.o = Vec3f(rng.UniformFloat() * 1.8f - 0.9f, rng.UniformFloat() * 1.8f + 0.1f, rng.UniformFloat() * 1.8f - 0.9f);
    r.d = SampleUniformSphere({rng.UniformFloat(), rng.UniformFloat()});
  }
  return rays;
}

void BM_IntersectClosest(benchmark::State& state) {
  const Scene& scene = *Cornell().scene;
  std::vector<Ray> rays = CornellRays(4096);
  size_t i = 0, hits = 0;
  for (auto _ : state) {
    auto si = scene.Intersect(rays[i++ & 4095]);
    hits += si.has_value();
    benchmark::DoNotOptimize(si);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["hit_fraction"] = double(hits) / state.iterations();
}
BENCHMARK(BM_IntersectClosest);

// A pixel's camera rays as the renderer makes them (64 jittered in one pixel of the 512 x 512
// Cornell camera), traced one by one (arg 0) or in packets by Scene::IntersectCoherent (arg 1).
void BM_IntersectCameraRays(benchmark::State& state) {
  const Scene& scene = *Cornell().scene;
  PCG32 rng(1, 1);
  const float t = std::tan(19.5f / 2 * kPi / 180);
  std::vector<std::vector<Ray>> pixels(256);
  for (std::vector<Ray>& rays : pixels) {
    float px = rng.UniformFloat() * 512, py = rng.UniformFloat() * 512;
    for (int k = 0; k < 64; ++k) {
      float x = (px + rng.UniformFloat()) / 256 - 1, y = 1 - (py + rng.UniformFloat()) / 256;
      rays.push_back(Ray{Vec3f(0, 1, 6.8f), Normalize(Vec3f(-x * t, y * t, -1))});
    }
  }
  std::vector<const Ray*> ptrs(64);
  std::vector<std::optional<SurfaceInteraction>> hits(64);
  size_t i = 0;
  for (auto _ : state) {
    const std::vector<Ray>& rays = pixels[i++ % pixels.size()];
    if (state.range(0) == 0) {
      for (int k = 0; k < 64; ++k) hits[k] = scene.Intersect(rays[k]);
    } else {
      for (int k = 0; k < 64; ++k) ptrs[k] = &rays[k];
      scene.IntersectCoherent(ptrs, hits);
    }
    benchmark::DoNotOptimize(hits.data());
  }
  state.SetItemsProcessed(state.iterations() * 64);
  state.SetLabel(state.range(0) ? "packets of 8" : "one by one");
}
BENCHMARK(BM_IntersectCameraRays)->Arg(0)->Arg(1);

void BM_Occluded(benchmark::State& state) {
  const Scene& scene = *Cornell().scene;
  std::vector<Ray> rays = CornellRays(4096);
  for (Ray& r : rays) r.tmax = 0.5f;
  size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(scene.Occluded(rays[i++ & 4095]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Occluded);

BSDF MakeBsdf(int kind) {
  SampledSpectrum s(0.5f);
  switch (kind) {
    case 0:
      return BSDF(Frame(), DiffuseBxDF{s}, false);
    case 1: {
      DielectricBxDF d;
      d.eta = 1.5f;
      return BSDF(Frame(), d, true);
    }
    case 2: {
      DielectricBxDF d;
      d.eta = 1.5f;
      d.distrib = TrowbridgeReitz(0.2f, 0.2f);
      return BSDF(Frame(), d, true);
    }
    case 3:
      return BSDF(Frame(), ConductorBxDF{SampledSpectrum(0.2f), SampledSpectrum(3.f), SampledSpectrum(1.f), TrowbridgeReitz(0.3f, 0.3f)}, false);
    default: {
      PlasticBxDF p;
      p.diffuse = s;
      p.fdr_int = FresnelDiffuseReflectance(1 / 1.49f);
      return BSDF(Frame(), p, false);
    }
  }
}

void BM_BsdfSample(benchmark::State& state) {
  BSDF bsdf = MakeBsdf(int(state.range(0)));
  PCG32 rng(2, 2);
  Vec3f wo = Normalize(Vec3f(0.3f, 0.2f, 0.9f));
  for (auto _ : state) {
    auto s = bsdf.Sample(wo, rng.UniformFloat(), {rng.UniformFloat(), rng.UniformFloat()});
    benchmark::DoNotOptimize(s);
  }
  state.SetItemsProcessed(state.iterations());
  static const char* names[] = {"diffuse", "dielectric", "roughdielectric", "roughconductor", "plastic"};
  state.SetLabel(names[state.range(0)]);
}
BENCHMARK(BM_BsdfSample)->DenseRange(0, 4);

void BM_BsdfEvalPdf(benchmark::State& state) {
  BSDF bsdf = MakeBsdf(int(state.range(0)));
  PCG32 rng(3, 3);
  Vec3f wo = Normalize(Vec3f(0.3f, 0.2f, 0.9f));
  for (auto _ : state) {
    Vec3f wi = SampleUniformSphere({rng.UniformFloat(), rng.UniformFloat()});
    benchmark::DoNotOptimize(bsdf.f(wo, wi));
    benchmark::DoNotOptimize(bsdf.Pdf(wo, wi));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_BsdfEvalPdf)->DenseRange(0, 4);

void BM_Sampler2D(benchmark::State& state) {
  auto s = std::make_unique<Sampler>(SamplerKind(state.range(0)), 64, 0);
  int i = 0;
  for (auto _ : state) {
    if ((i & 15) == 0) s->StartPixelSample({i & 511, 7}, (i >> 4) & 63);
    ++i;
    benchmark::DoNotOptimize(s->Get2D());
  }
  state.SetItemsProcessed(state.iterations());
  static const char* names[] = {"independent", "stratified", "sobol"};
  state.SetLabel(names[state.range(0)]);
}
BENCHMARK(BM_Sampler2D)->DenseRange(0, 2);

// Rays from uniform points on a 36 x 24 mm film toward uniform points on the rear element of
// the double Gauss at full aperture; every launched ray counts, blocked or not.
struct LensBenchRays {
  LensSystem tracer;
  std::vector<LensRay> rays;
  std::vector<float> lambdas;
  LensBenchRays() : tracer(LoadLens("dgauss.50mm")) {
    tracer.SetBackFocus(ComputeParaxial(tracer.prescription()).bfl);
    PCG32 rng(5, 5);
    const LensSurface& rear = tracer.prescription().surfaces.back();
    double rear_z = tracer.VertexZ(int(tracer.prescription().surfaces.size()) - 1);
    for (int i = 0; i < 8192; ++i) {
      Vec3d film((rng.UniformFloat() - 0.5) * 36, (rng.UniformFloat() - 0.5) * 24, tracer.FilmZ());
      double a = 2 * M_PI * rng.UniformFloat(), r = rear.semi_diameter * std::sqrt(rng.UniformFloat());
      Vec3d target(r * std::cos(a), r * std::sin(a), rear_z);
      rays.push_back({film, Normalize(target - film)});
      lambdas.push_back(400 + 300 * rng.UniformFloat());
    }
  }
};

void BM_LensDoubleFromFilm(benchmark::State& state) {
  static LensBenchRays setup;
  size_t i = 0, passed = 0;
  for (auto _ : state) {
    TraceResult r = TraceFromFilm(setup.tracer, setup.rays[i & 8191], setup.lambdas[i & 8191]);
    passed += r.ray.has_value();
    ++i;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["pass_fraction"] = double(passed) / state.iterations();
}
BENCHMARK(BM_LensDoubleFromFilm);

void BM_LensBatchFromFilm(benchmark::State& state) {
  static LensBenchRays setup;
  BatchLensTracer fast(setup.tracer);
  RayBatch batch;
  const size_t n = 8192;
  for (auto _ : state) {
    state.PauseTiming();
    batch.Resize(n);
    for (size_t i = 0; i < n; ++i) {
      const LensRay& r = setup.rays[i];
      batch.ox[i] = float(r.o.x), batch.oy[i] = float(r.o.y), batch.oz[i] = float(r.o.z);
      batch.dx[i] = float(r.d.x), batch.dy[i] = float(r.d.y), batch.dz[i] = float(r.d.z);
      batch.lambda[i] = setup.lambdas[i];
    }
    state.ResumeTiming();
    fast.TraceFromFilm(batch, state.range(0) != 0);
    benchmark::DoNotOptimize(batch.alive.data());
  }
  state.SetItemsProcessed(state.iterations() * n);
  state.SetLabel(state.range(0) ? "with transmission" : "geometry only");
}
BENCHMARK(BM_LensBatchFromFilm)->Arg(0)->Arg(1);

}  // namespace
}  // namespace objektiv

BENCHMARK_MAIN();
