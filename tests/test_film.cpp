// The film as integrators write it (render/block_context.h): splats at any film position from
// many threads, spread by the normalised filter and added to the image; sample ranges rendered
// one after another; the filters' integrals that normalise splats.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <functional>

#include "render_helpers.h"

namespace objektiv {
namespace {

// Integral of each filter's Evaluate by the midpoint rule on a fine grid.
TEST(Filter, IntegralMatchesTheIntegralOfEvaluate) {
  const BoxFilter box_half(0.5f), box_wide(1.5f);
  const TentFilter tent(1.f), tent_wide(2.f);
  const GaussianFilter gauss(0.5f), gauss_wide(0.8f);
  const BlackmanHarrisFilter bh(1.5f), bh_wide(2.f);
  for (const Filter* f : std::initializer_list<const Filter*>{&box_half, &box_wide, &tent, &tent_wide, &gauss,
                                                                &gauss_wide, &bh, &bh_wide}) {
    const int n = 1000;
    const double r = f->Radius(), h = 2 * r / n;
    double sum = 0;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) sum += f->Evaluate(Vec2f(float(-r + (x + 0.5) * h), float(-r + (y + 0.5) * h)));
    EXPECT_NEAR(f->Integral(), sum * h * h, 1e-5 * sum * h * h) << "radius " << r;
  }
}

std::string FilmScene(const std::string& rfilter, const std::string& crop = "") {
  return fmt::format(R"(<scene version="3.0.0">
  <sensor type="perspective"><float name="fov" value="40"/>
    <sampler type="independent"><integer name="sample_count" value="64"/></sampler>
    <film type="hdrfilm"><integer name="width" value="32"/><integer name="height" value="24"/>{}
      <rfilter type="{}"/></film></sensor>
  <emitter type="constant"/>
</scene>)",
                     crop, rfilter);
}

// One splat: where on the film (full-film pixel coordinates) and how much.
struct Splat {
  Vec2f p;
  SampledSpectrum L;
  SampledWavelengths lambda;
};
// A splat as a pure function of (pixel, sample index) and the sampler started there.
using SplatFn = std::function<Splat(Vec2i pixel, int index, Sampler& sampler)>;

// A test integrator written against the block contract alone: for every (pixel, sample index)
// of its block it splats a contribution anywhere on the film (in other blocks' pixels too),
// `repeat` times.
class SplatIntegrator final : public Integrator {
 public:
  SplatIntegrator(const Scene& scene, SplatFn splat, int repeat)
      : Integrator(scene), splat_(std::move(splat)), repeat_(repeat) {}
  void RenderBlock(BlockContext& ctx) const override {
    Sampler sampler = ctx.sampler();
    ctx.ForEachPixel([&](Vec2i pixel, SampleRange samples) {
      for (int s = samples.begin; s < samples.end; ++s) {
        sampler.StartPixelSample(pixel, s);
        Splat sp = splat_(pixel, s, sampler);
        for (int i = 0; i < repeat_; ++i) ctx.AddSplat(sp.p, sp.L, sp.lambda);
      }
    });
  }

 private:
  SplatFn splat_;
  int repeat_;
};

struct SplatRender {
  Image image;
  RenderStats stats;
};

// Renders the sample ranges [ranges[i], ranges[i+1]) one after another into one film.
SplatRender RenderSplats(const RenderSetup& setup, const SplatFn& splat, int threads, int tile_size,
                         std::vector<int> ranges = {0, 64}, int repeat = 1) {
  std::unique_ptr<Sampler> sampler = MakeSampler(setup.sampler);
  Film film(setup.film.width, setup.film.height, setup.film.crop, setup.film.filter);
  SplatIntegrator integrator(*setup.scene, splat, repeat);
  SplatRender out;
  for (size_t i = 0; i + 1 < ranges.size(); ++i) {
    RenderOptions opt;
    opt.spp_begin = ranges[i];
    opt.spp_end = ranges[i + 1];
    opt.threads = threads;
    opt.tile_size = tile_size;
    RenderStats stats = Render(*setup.camera, integrator, *sampler, film, opt);
    out.stats.samples += stats.samples;
    out.stats.nan_count += stats.nan_count;
    out.stats.inf_count += stats.inf_count;
    out.stats.pixels_completed = stats.pixels_completed;
  }
  EXPECT_EQ(film.samples_per_pixel(), ranges.back() - ranges.front());
  out.image = film.ToImage(*setup.film.color_space);
  return out;
}

// Every splat a whole pixel's centre with the same spectrum, 16 times over: half of them on a
// 2x2 patch (the threads add to the same pixels at once), half anywhere. Sums of equal values
// are exact in double, so the image must be exactly count * value / spp on any thread count.
TEST(FilmSplat, SumsExactlyWhatWasSplattedFromManyThreads) {
  RenderSetup setup = LoadSceneFromString(FilmScene("box"), "splat.xml", {});
  const SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.3f);
  const SplatFn splat = [&](Vec2i, int index, Sampler& sampler) {
    Vec2f u = sampler.Get2D();
    Vec2i to = index % 2 ? Vec2i(10 + int(2 * u.x), 7 + int(2 * u.y)) : Vec2i(int(32 * u.x), int(24 * u.y));
    return Splat{Vec2f(to.x + 0.5f, to.y + 0.5f), SampledSpectrum(0.75f), lambda};
  };
  // The counts per pixel, made here one splat after another.
  std::vector<int> count(32 * 24, 0);
  Sampler sampler = *MakeSampler(setup.sampler);
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x)
      for (int s = 0; s < 64; ++s) {
        sampler.StartPixelSample(Vec2i(x, y), s);
        Splat sp = splat(Vec2i(x, y), s, sampler);
        ++count[int(sp.p.y) * 32 + int(sp.p.x)];
      }
  const Vec3f xyz = SampledToXYZ(SampledSpectrum(0.75f), lambda);
  EXPECT_GT(count[7 * 32 + 10], 64 * 32 * 24 / 2 / 4 / 2);
  for (auto [threads, tiles] : {std::pair{1, 16}, {2, 16}, {2, 5}, {7, 3}}) {
    SplatRender r = RenderSplats(setup, splat, threads, tiles, {0, 64}, 16);
    EXPECT_EQ(r.stats.samples, 64u * 32 * 24);
    EXPECT_EQ(r.stats.pixels_completed, 32u * 24);
    for (int y = 0; y < 24; ++y)
      for (int x = 0; x < 32; ++x) {
        const double k = 16 * count[y * 32 + x] / 64.0;
        const Vec3f expected =
            setup.film.color_space->ToRGB(Vec3f(float(k * xyz.x), float(k * xyz.y), float(k * xyz.z)));
        for (int c = 0; c < 3; ++c)
          ASSERT_EQ(r.image.At(x, y, c), expected[c]) << x << "," << y << " threads " << threads << " tiles " << tiles;
      }
  }
}

// Splats at any position (also outside the crop window), of any value and wavelengths, spread
// over the pixels within the filter's radius by f(p - centre) / integral of f: against the same
// sums made here one after another, on 1 and 2 threads.
TEST(FilmSplat, SpreadsEachSplatByTheNormalisedFilter) {
  for (const char* rfilter : {"tent", "gaussian"}) {
    RenderSetup setup = LoadSceneFromString(
        FilmScene(rfilter, R"(<integer name="crop_offset_x" value="3"/><integer name="crop_offset_y" value="2"/>
      <integer name="crop_width" value="25"/><integer name="crop_height" value="19"/>)"),
        "splat.xml", {});
    const CropWindow crop = setup.film.crop;
    ASSERT_EQ(crop.Width(), 25);
    const SplatFn splat = [](Vec2i, int, Sampler& sampler) {
      Vec2f u = sampler.Get2D();
      SampledWavelengths lambda = SampledWavelengths::SampleVisible(sampler.Get1D());
      return Splat{Vec2f(-2 + 36 * u.x, -2 + 28 * u.y), SampledSpectrum(0.1f + sampler.Get1D()), lambda};
    };
    const Filter& f = *setup.film.filter;
    std::vector<Vec3d> sum(size_t(crop.Width()) * crop.Height(), Vec3d(0.0));
    Vec3d total(0.0), total_inside(0.0);
    Sampler sampler = *MakeSampler(setup.sampler);
    for (int y = crop.y0; y < crop.y1; ++y)
      for (int x = crop.x0; x < crop.x1; ++x)
        for (int s = 0; s < 64; ++s) {
          sampler.StartPixelSample(Vec2i(x, y), s);
          Splat sp = splat(Vec2i(x, y), s, sampler);
          Vec3f xyz = SampledToXYZ(sp.L, sp.lambda);
          for (int py = crop.y0; py < crop.y1; ++py)
            for (int px = crop.x0; px < crop.x1; ++px) {
              double w = f.Evaluate(Vec2f(sp.p.x - (px + 0.5f), sp.p.y - (py + 0.5f))) / double(f.Integral());
              sum[size_t(py - crop.y0) * crop.Width() + (px - crop.x0)] += Vec3d(xyz.x, xyz.y, xyz.z) * w;
            }
          total += Vec3d(xyz.x, xyz.y, xyz.z);
          // Footprint (tent: radius 1) inside the crop window.
          if (sp.p.x > crop.x0 + 1.5 && sp.p.x < crop.x1 - 1.5 && sp.p.y > crop.y0 + 1.5 && sp.p.y < crop.y1 - 1.5)
            total_inside += Vec3d(xyz.x, xyz.y, xyz.z);
        }
    SplatRender one = RenderSplats(setup, splat, 1, 16), two = RenderSplats(setup, splat, 2, 5);
    ASSERT_EQ(one.image.width, crop.Width());
    Vec3d image_total(0.0);
    for (int y = 0; y < crop.Height(); ++y)
      for (int x = 0; x < crop.Width(); ++x) {
        Vec3d s = sum[size_t(y) * crop.Width() + x] / 64.0;
        Vec3f expected = setup.film.color_space->ToRGB(Vec3f(float(s.x), float(s.y), float(s.z)));
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(one.image.At(x, y, c), expected[c], 1e-5 * std::abs(expected[c]) + 1e-7) << rfilter << x << "," << y;
          // Only the order of the double sums differs between the two.
          EXPECT_NEAR(two.image.At(x, y, c), one.image.At(x, y, c), 1e-6 * std::abs(one.image.At(x, y, c)));
          image_total[c] += one.image.At(x, y, c);
        }
      }
    if (std::string(rfilter) == "tent") {
      // The tent is a partition of unity: everything splatted inside adds up; splats near the
      // edges lose the part of their footprint outside the crop window.
      double y = setup.film.color_space->ToXYZ(Vec3f(float(image_total.x), float(image_total.y), float(image_total.z))).y;
      EXPECT_GT(y, (1 - 1e-5) * total_inside.y / 64);
      EXPECT_LT(y, (1 + 1e-5) * total.y / 64);
      EXPECT_GT(total_inside.y, 0.2 * total.y);
    }
  }
}

// Splats of non-finite value or position are counted as the camera samples' are, and dropped.
TEST(FilmSplat, NonFiniteSplatsAreCountedAndDropped) {
  RenderSetup setup = LoadSceneFromString(FilmScene("box"), "splat.xml", {});
  const SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const SplatFn splat = [&](Vec2i pixel, int index, Sampler&) {
    Vec2f centre(pixel.x + 0.5f, pixel.y + 0.5f);
    switch (index) {
      case 0: return Splat{centre, SampledSpectrum(nan), lambda};
      case 1: return Splat{centre, SampledSpectrum(inf), lambda};
      case 2: return Splat{Vec2f(nan, centre.y), SampledSpectrum(1.f), lambda};
      case 3: return Splat{Vec2f(centre.x, inf), SampledSpectrum(1.f), lambda};
      case 4: return Splat{Vec2f(1e30f, -1e30f), SampledSpectrum(1.f), lambda};  // far outside: nothing
      default: return Splat{centre, SampledSpectrum(1.f), lambda};
    }
  };
  SplatRender r = RenderSplats(setup, splat, 2, 8);
  EXPECT_EQ(r.stats.nan_count, 3u * 32 * 24);
  EXPECT_EQ(r.stats.inf_count, 1u * 32 * 24);
  const Vec3f xyz = SampledToXYZ(SampledSpectrum(1.f), lambda);
  const double k = (64 - 5) / 64.0;
  const Vec3f expected = setup.film.color_space->ToRGB(Vec3f(float(k * xyz.x), float(k * xyz.y), float(k * xyz.z)));
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) ASSERT_EQ(r.image.At(x, y, c), expected[c]) << x << "," << y;
}

// A render split into sample ranges, rendered one after another into the film, is the render
// of all of them: bit for bit for camera samples (each pixel's sums are made in sample order),
// and for splats whose sums are exact.
TEST(FilmSplat, SampleRangesRenderedOneAfterAnotherAddUp) {
  RenderSetup setup = LoadSceneFromString(FilmScene("box"), "splat.xml", {});
  const SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.7f);
  const SplatFn splat = [&](Vec2i, int, Sampler& sampler) {
    Vec2f u = sampler.Get2D();
    return Splat{Vec2f(int(32 * u.x) + 0.5f, int(24 * u.y) + 0.5f), SampledSpectrum(2.f), lambda};
  };
  SplatRender whole = RenderSplats(setup, splat, 2, 16), parts = RenderSplats(setup, splat, 2, 16, {0, 5, 40, 64});
  EXPECT_EQ(parts.stats.samples, whole.stats.samples);
  EXPECT_EQ(parts.image.pixels, whole.image.pixels);
  // Half the samples: half the splats over half the samples per pixel, the same mean.
  SplatRender half = RenderSplats(setup, splat, 2, 16, {0, 32});
  double sum_whole = 0, sum_half = 0;
  for (size_t i = 0; i < whole.image.pixels.size(); ++i) sum_whole += whole.image.pixels[i], sum_half += half.image.pixels[i];
  EXPECT_NEAR(sum_half, sum_whole, 1e-6 * sum_whole);

  // The path tracer through the camera-path block loop.
  RenderSetup box = LoadSceneFromString(R"(<scene version="3.0.0">
  <integrator type="path"><integer name="max_depth" value="4"/></integrator>
  <sensor type="perspective"><float name="fov" value="40"/>
    <transform name="to_world"><lookat origin="0, 1, 3.5" target="0, 1, 0" up="0, 1, 0"/></transform>
    <sampler type="sobol"><integer name="sample_count" value="8"/></sampler>
    <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="12"/></film></sensor>
  <emitter type="constant"><rgb name="radiance" value="0.5, 0.6, 0.7"/></emitter>
  <shape type="sphere"><point name="center" value="0, 1, 0"/><float name="radius" value="0.5"/></shape>
  <shape type="rectangle"><transform name="to_world"><rotate x="1" angle="-90"/><scale value="3"/></transform></shape>
</scene>)",
                                        "box.xml", {});
  std::unique_ptr<Sampler> sampler = MakeSampler(box.sampler);
  auto render = [&](std::vector<int> ranges) {
    Film film(box.film.width, box.film.height, box.film.crop, box.film.filter);
    for (size_t i = 0; i + 1 < ranges.size(); ++i) {
      RenderOptions opt;
      opt.spp_begin = ranges[i];
      opt.spp_end = ranges[i + 1];
      opt.threads = 2;
      Render(*box.camera, *box.integrator, *sampler, film, opt);
    }
    return film.ToImage(*box.film.color_space);
  };
  Image one = render({0, 8}), three = render({0, 3, 5, 8});
  EXPECT_EQ(one.pixels, three.pixels);
  EXPECT_GT(test::ChannelMean(one, 1).mean, 0.05);
}

}  // namespace
}  // namespace objektiv
