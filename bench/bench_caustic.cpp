// The caustic scene: time to a relative error of 5% in the caustic, per integrator. The scene
// is the one of tests/test_sppm.cpp: a glass ball (index 1.5) on a floor under a point light
// low to its left, the camera above the caustic's patch of floor (64 x 64 pixels). The
// reference is the mean of two long light-tracer renders (unbiased, 16384 samples per pixel
// each, two seeds); the caustic is its pixels brighter than twice the image's mean. Two errors
// of a render: the caustic's light (the sum of Y over those pixels) against the reference's,
// relative; and the RMS over those pixels of (Y - Y_ref), over the mean reference Y there (per
// pixel: the noise, and sppm's blur at the caustic's sharp edges), with the reference's own
// noise taken out (measured from the difference of its two halves: RMS(a - b) / 2 is the
// noise of their mean). Each integrator renders with 1, 2, 4, ... samples per pixel (sppm:
// iterations of 50 000 photons) until both are below 5% (or a step takes over a minute); the
// table shows each step's time and errors, all on every core.
// The path tracer without `caustics` never gets there: no camera path finds a point light
// through glass, the caustic stays black (error 100% at any time); it is shown for 64 spp.
// Run: build/objektiv-bench --benchmark_filter=Caustic
#include <benchmark/benchmark.h>

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "io/scene_loader.h"
#include "render/renderer.h"

namespace objektiv {
namespace {

std::string CausticScene(const std::string& integrator, int spp, int seed) {
  return fmt::format(R"(<scene version="3.0.0">
  {}
  <sensor type="perspective"><float name="fov" value="15"/>
    <transform name="to_world"><lookat origin="2.6, 3.5, 0" target="0.95, 0, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="{}"/><integer name="seed" value="{}"/></sampler>
    <film type="hdrfilm"><integer name="width" value="64"/><integer name="height" value="64"/><rfilter type="box"/></film>
  </sensor>
  <shape type="rectangle"><transform name="to_world"><scale value="4"/><rotate x="1" angle="-90"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.6, 0.5, 0.4"/></bsdf></shape>
  <shape type="sphere"><point name="center" x="0" y="0.35" z="0"/><float name="radius" value="0.35"/>
    <bsdf type="dielectric"><float name="int_ior" value="1.5"/></bsdf></shape>
  <emitter type="point"><point name="position" x="-1.5" y="0.9" z="0"/><rgb name="intensity" value="3, 3, 3"/></emitter>
</scene>)",
                     integrator, spp, seed);
}

struct Rendered {
  std::vector<double> Y;
  double seconds;
};
// The reference takes another seed than the renders measured against it.
Rendered RenderY(const std::string& integrator, int spp, int seed = 0) {
  const RenderSetup setup = LoadSceneFromString(CausticScene(integrator, spp, seed), "caustic.xml", {});
  std::unique_ptr<Sampler> sampler = MakeSampler(setup.sampler);
  Film film(setup.film.width, setup.film.height, setup.film.crop, setup.film.filter);
  RenderOptions options;
  options.spp_end = spp;
  const RenderStats stats = Render(*setup.camera, *setup.integrator, *sampler, film, options);
  const Image img = film.ToImage(*setup.film.color_space);
  Rendered r{{}, stats.seconds};
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const Vec3f c = img.Rgb(x, y);
      r.Y.push_back(0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z);
    }
  return r;
}

void BM_CausticTimeTo5Percent(benchmark::State& state) {
  spdlog::set_level(spdlog::level::warn);
  for (auto _ : state) {
    const Rendered ref_a = RenderY(R"(<integrator type="ptracer"/>)", 16384, 1000),
                   ref_b = RenderY(R"(<integrator type="ptracer"/>)", 16384, 2000);
    Rendered ref{{}, ref_a.seconds + ref_b.seconds};
    for (size_t i = 0; i < ref_a.Y.size(); ++i) ref.Y.push_back(0.5 * (ref_a.Y[i] + ref_b.Y[i]));
    double mean = 0;
    for (double y : ref.Y) mean += y / ref.Y.size();
    std::vector<size_t> caustic;
    double ref_mean = 0;
    for (size_t i = 0; i < ref.Y.size(); ++i)
      if (ref.Y[i] > 2 * mean) caustic.push_back(i), ref_mean += ref.Y[i];
    ref_mean /= double(caustic.size());
    double floor2 = 0;
    for (size_t i : caustic) floor2 += (ref_a.Y[i] - ref_b.Y[i]) * (ref_a.Y[i] - ref_b.Y[i]) / 4;
    floor2 /= double(caustic.size()) * ref_mean * ref_mean;
    std::printf("reference: ptracer 2 x 16384 spp, %.1f s; caustic: %zu of %zu pixels; its own per-pixel noise %.2f%%\n",
                ref.seconds, caustic.size(), ref.Y.size(), 100 * std::sqrt(floor2));
    auto error = [&](const Rendered& r) {
      double s = 0;
      for (size_t i : caustic) s += (r.Y[i] - ref.Y[i]) * (r.Y[i] - ref.Y[i]);
      return std::sqrt(std::max(0.0, s / (double(caustic.size()) * ref_mean * ref_mean) - floor2));
    };
    auto total_error = [&](const Rendered& r) {
      double sum = 0;
      for (size_t i : caustic) sum += r.Y[i];
      return std::abs(sum / double(caustic.size()) - ref_mean) / ref_mean;
    };
    const struct {
      const char* name;
      const char* xml;
    } integrators[] = {
        {"path (caustics)", R"(<integrator type="path"><boolean name="caustics" value="true"/></integrator>)"},
        {"ptracer", R"(<integrator type="ptracer"/>)"},
        {"sppm (50k photons)", R"(<integrator type="sppm"><integer name="photon_count" value="50000"/></integrator>)"},
    };
    for (const auto& in : integrators) {
      std::printf("%s (spp: seconds, total error, per-pixel RMS error)\n ", in.name);
      bool total_reached = false;
      for (int spp = 1; spp <= 65536; spp *= 2) {
        const Rendered r = RenderY(in.xml, spp);
        const double e = error(r), t = total_error(r);
        std::printf(" | %d: %.3g s %.1f%% %.1f%%", spp, r.seconds, 100 * t, 100 * e);
        if (t < 0.05 && !total_reached) {
          std::printf(" [total within 5%%]");
          total_reached = true;
        }
        if (e < 0.05) {
          std::printf(" [per pixel within 5%%]");
          break;
        }
        if (r.seconds > 60) break;
      }
      std::printf("\n");
    }
    const Rendered path = RenderY(R"(<integrator type="path"/>)", 64);
    std::printf("path (no caustics) | 64: %.3g s %.1f%% %.1f%% (never: no camera path finds the point light through "
                "the glass)\n",
                path.seconds, 100 * total_error(path), 100 * error(path));
  }
}
BENCHMARK(BM_CausticTimeTo5Percent)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
}  // namespace objektiv
