// Pixel sample patterns (render/pixel_pattern.h) and adaptive sampling
// (render/adaptive_sampling.h): the patterns' exact positions and weights and their shifted
// rounds; statistical adaptive sampling spends fewer samples on flat regions than on an edge,
// renders the fixed-rate image within its measured noise, the same on any thread count and
// however its samples were grouped into passes; classic (whitted) adaptive supersampling
// subdivides at edges only, and deeper subdivision comes closer to the converged image.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "base/error.h"
#include "image_estimates.h"
#include "render/adaptive_sampling.h"
#include "render/progressive_render.h"
#include "render_helpers.h"
#include "sanitizer_build.h"

namespace objektiv {
namespace {

using test::kSize;

// ---- patterns ------------------------------------------------------------------------------

std::vector<PatternSample> Pattern(PixelPattern p, int spp, Vec2i pixel, int first, int n) {
  Sampler s(SamplerKind::kSobol, spp, 7, p);
  std::vector<PatternSample> out;
  for (int i = first; i < first + n; ++i) {
    s.StartPixelSample(pixel, i);
    out.push_back(s.GetPixelSample());
  }
  return out;
}

void ExpectAt(const PatternSample& s, Vec2f u, float weight, const std::string& what) {
  EXPECT_NEAR(s.u.x, u.x, 1e-6) << what;
  EXPECT_NEAR(s.u.y, u.y, 1e-6) << what;
  EXPECT_FLOAT_EQ(s.weight, weight) << what;
}

TEST(PixelPatterns, GridPutsTheCellCentres) {
  const auto g = Pattern(PixelPattern::kGrid, 16, Vec2i(3, 5), 0, 16);
  for (int j = 0; j < 16; ++j) ExpectAt(g[j], Vec2f((j % 4 + 0.5f) / 4, (j / 4 + 0.5f) / 4), 1, fmt::format("grid {}", j));
  // 10 samples: rounds of the 3 x 3 grid, the tenth the first of a shifted round.
  const auto g3 = Pattern(PixelPattern::kGrid, 10, Vec2i(3, 5), 0, 9);
  for (int j = 0; j < 9; ++j) ExpectAt(g3[j], Vec2f((j % 3 + 0.5f) / 3, (j / 3 + 0.5f) / 3), 1, fmt::format("grid3 {}", j));
  EXPECT_EQ(PatternRoundSize(PixelPattern::kGrid, 10), 9);
  EXPECT_EQ(PatternRoundSize(PixelPattern::kGrid, 2), 1);
}

TEST(PixelPatterns, RgssIsTheRotatedGrid) {
  const auto r = Pattern(PixelPattern::kRgss, 4, Vec2i(0, 0), 0, 4);
  const Vec2f expected[4] = {{0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}};
  for (int j = 0; j < 4; ++j) ExpectAt(r[j], expected[j], 1, fmt::format("rgss {}", j));
  // One sample in each row and each column of the 4 x 4 subgrid.
  int rows = 0, cols = 0;
  for (int j = 0; j < 4; ++j) rows |= 1 << int(r[j].u.y * 4), cols |= 1 << int(r[j].u.x * 4);
  EXPECT_EQ(rows, 15);
  EXPECT_EQ(cols, 15);
}

TEST(PixelPatterns, QuincunxIsTheCentreAndTheCorners) {
  const auto q = Pattern(PixelPattern::kQuincunx, 9, Vec2i(2, 1), 0, 9);
  ExpectAt(q[0], Vec2f(0.5f, 0.5f), 2.5f, "centre");
  const Vec2f corners[4] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  for (int j = 0; j < 4; ++j) ExpectAt(q[1 + j], corners[j], 0.625f, fmt::format("corner {}", j));
  // The round's weights: centre 1/2, corners 1/8 each.
  EXPECT_FLOAT_EQ(q[0].weight / (q[0].weight + 4 * q[1].weight), 0.5f);
  // Later rounds: the quincunx lattice shifted, two points half a pixel apart on both axes.
  for (int r = 0; r < 2; ++r) {
    const PatternSample& c = q[5 + 2 * r];
    const PatternSample& k = q[6 + 2 * r];
    const float dx = std::fmod(c.u.x - k.u.x + 1.f, 1.f), dy = std::fmod(c.u.y - k.u.y + 1.f, 1.f);
    EXPECT_NEAR(dx, 0.5f, 1e-5) << r;
    EXPECT_NEAR(dy, 0.5f, 1e-5) << r;
    EXPECT_EQ(c.weight, 1.f);
    EXPECT_EQ(k.weight, 1.f);
  }
}

// A shifted round is the pattern moved as a whole; the shifts are uniform over pixels (the mean
// of a round's first point over many pixels is the pixel's centre, within 4 standard errors of
// a uniform variable: 0.2887 / sqrt(n)).
TEST(PixelPatterns, LaterRoundsAreTheShiftedPatternUniformOverPixels) {
  constexpr int kPixels = 4000;
  double sx = 0, sy = 0;
  for (int p = 0; p < kPixels; ++p) {
    const auto r = Pattern(PixelPattern::kRgss, 8, Vec2i(p % 64, p / 64), 4, 4);
    for (int j = 1; j < 4; ++j) {  // the round's shape: the round-0 differences, modulo 1
      const Vec2f base[4] = {{0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}};
      const float dx = std::fmod(r[j].u.x - r[0].u.x + 2.f, 1.f), ex = std::fmod(base[j].x - base[0].x + 2.f, 1.f);
      const float dy = std::fmod(r[j].u.y - r[0].u.y + 2.f, 1.f), ey = std::fmod(base[j].y - base[0].y + 2.f, 1.f);
      ASSERT_NEAR(std::min(std::abs(dx - ex), 1 - std::abs(dx - ex)), 0, 1e-5) << p << " " << j;
      ASSERT_NEAR(std::min(std::abs(dy - ey), 1 - std::abs(dy - ey)), 0, 1e-5) << p << " " << j;
    }
    sx += r[0].u.x, sy += r[0].u.y;
  }
  const double se = 0.2887 / std::sqrt(double(kPixels));
  EXPECT_NEAR(sx / kPixels, 0.5, 4 * se);
  EXPECT_NEAR(sy / kPixels, 0.5, 4 * se);
}

// ---- scenes --------------------------------------------------------------------------------

// A bright rectangle (an area light, radiance 1) seen head-on by a pinhole camera over a black
// background, its edge tilted by 20 degrees through the middle of the 32 x 32 image: the flat
// pixels on either side, and the edge between.
// `full`: the rectangle covers the whole view (the lit value of every pixel, at the same
// wavelength samples as the edge scene's).
std::string EdgeScene(const std::string& integrator, const std::string& sampler, bool full = false) {
  return fmt::format(R"(<scene version="3.0.0">
  <integrator type="{}"/>
  <sensor type="perspective"><float name="fov" value="40"/>
    <transform name="to_world"><lookat origin="0, 0, 4" target="0, 0, 0" up="0, 1, 0"/></transform>
    {}
    <film type="hdrfilm"><integer name="width" value="{}"/><integer name="height" value="{}"/><rfilter type="box"/></film>
  </sensor>
  <shape type="rectangle">
    <transform name="to_world">{}</transform>
    <emitter type="area"><rgb name="radiance" value="1, 1, 1"/></emitter></shape>
</scene>)",
                     integrator, sampler, kSize, kSize,
                     full ? R"(<scale value="4"/>)" : R"(<scale value="3"/><translate x="-2.987"/><rotate z="1" angle="20"/>)");
}

std::string SamplerXml(const std::string& type, int spp, int seed, const std::string& more = "") {
  return fmt::format(R"(<sampler type="{}"><integer name="sample_count" value="{}"/><integer name="seed" value="{}"/>{}</sampler>)",
                     type, spp, seed, more);
}

std::string Statistical(double threshold, int min) {
  return fmt::format(R"(<string name="adaptive" value="statistical"/><float name="adaptive_threshold" value="{}"/>)"
                     R"(<integer name="adaptive_min_samples" value="{}"/>)",
                     threshold, min);
}

struct Rendered {
  Image image;
  std::vector<uint32_t> counts;
  RenderStats stats;
};

Rendered Render(const std::string& xml, int threads = 0, int tile_size = 16) {
  RenderSetup setup = LoadSceneFromString(xml, "test.xml", {});
  std::unique_ptr<Sampler> sampler = MakeSampler(setup.sampler);
  Film film(setup.film.width, setup.film.height, setup.film.crop, setup.film.filter);
  RenderOptions opt;
  opt.spp_end = sampler->adaptive().mode == AdaptiveMode::kWhitted ? 1 : sampler->spp();
  opt.threads = threads;
  opt.tile_size = tile_size;
  Rendered r;
  r.stats = Render(*setup.camera, *setup.integrator, *sampler, film, opt);
  r.image = film.ToImage(*setup.film.color_space);
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) r.counts.push_back(film.SampleCount(Vec2i(x, y)));
  return r;
}

double Luminance(const Image& img, int x, int y) {
  return 0.2126 * img.At(x, y, 0) + 0.7152 * img.At(x, y, 1) + 0.0722 * img.At(x, y, 2);
}

// Pixels of the edge scene by what a converged render shows: flat (all light or all dark, and
// so are their 8 neighbours) and edge (the edge crosses them: between 10% and 90% lit).
struct Regions {
  std::vector<int> flat_lit, flat_dark, edge;
};
Regions Classify() {
  const Image ref = Render(EdgeScene("path", SamplerXml("stratified", 256, 99))).image;
  double lit = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) lit = std::max(lit, Luminance(ref, x, y));
  Regions r;
  for (int y = 1; y < kSize - 1; ++y)
    for (int x = 1; x < kSize - 1; ++x) {
      double lo = 1e30, hi = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          lo = std::min(lo, Luminance(ref, x + dx, y + dy)), hi = std::max(hi, Luminance(ref, x + dx, y + dy));
      const double f = Luminance(ref, x, y) / lit;
      if (lo > 0.98 * lit) r.flat_lit.push_back(y * kSize + x);
      else if (hi < 0.02 * lit) r.flat_dark.push_back(y * kSize + x);
      else if (f > 0.1 && f < 0.9) r.edge.push_back(y * kSize + x);
    }
  return r;
}

double MeanCount(const std::vector<uint32_t>& counts, const std::vector<int>& pixels) {
  double s = 0;
  for (int i : pixels) s += counts[i];
  return s / double(pixels.size());
}

// ---- statistical adaptive sampling ---------------------------------------------------------

TEST(AdaptiveSampling, StatisticalSpendsFewerSamplesOnFlatRegionsThanOnTheEdge) {
  const Regions regions = Classify();
  ASSERT_GT(regions.flat_lit.size(), 50u);
  ASSERT_GT(regions.flat_dark.size(), 50u);
  ASSERT_GT(regions.edge.size(), 15u);
  const Rendered r = Render(EdgeScene("path", SamplerXml("sobol", 256, 1, Statistical(0.02, 16))));
  const double lit = MeanCount(r.counts, regions.flat_lit), dark = MeanCount(r.counts, regions.flat_dark),
               edge = MeanCount(r.counts, regions.edge);
  RecordProperty("samples_flat_lit", fmt::format("{:.1f}", lit));
  RecordProperty("samples_flat_dark", fmt::format("{:.1f}", dark));
  RecordProperty("samples_edge", fmt::format("{:.1f}", edge));
  std::printf("samples per pixel: flat lit %.1f, flat dark %.1f, edge %.1f (min 16, cap 256)\n", lit, dark, edge);
  // A black pixel's samples all agree: it is judged from 4 pilots on, and stops at the first
  // look there (16, 20, 25, 32, 40, 50, 63, 79: at 79).
  AdaptiveSettings settings;
  settings.mode = AdaptiveMode::kStatistical;
  settings.min_samples = 16;
  const int first_look = NextAdaptiveCheck(settings, kAgreeingSamplesFactor * 16 - 1);
  EXPECT_EQ(first_look, 79);
  EXPECT_EQ(dark, first_look);
  EXPECT_LT(lit, 0.5 * edge);
  EXPECT_GT(edge, 48);
  // Every pixel between the pilot and the cap, and the stats count what the film holds.
  uint64_t total = 0;
  for (uint32_t n : r.counts) {
    EXPECT_GE(n, 16u);
    EXPECT_LE(n, 256u);
    total += n;
  }
  EXPECT_EQ(r.stats.samples, total);
  EXPECT_EQ(r.stats.pixels_completed, r.stats.pixels);
}

// A noisy image (a floor lit by a small sphere light past an occluder: penumbra and path-traced
// noise): the adaptive image's 8 x 8 blocks equal a fixed-rate render's within their measured
// noise over 8 seeds. The adaptive renders are cheaper (fewer samples in all).
std::string NoisyScene(const std::string& sampler) {
  return fmt::format(R"(<scene version="3.0.0">
  <integrator type="path"><integer name="max_depth" value="3"/></integrator>
  <sensor type="perspective"><float name="fov" value="45"/>
    <transform name="to_world"><lookat origin="0, 1.5, 3" target="0, 0.2, 0" up="0, 1, 0"/></transform>
    {}
    <film type="hdrfilm"><integer name="width" value="{}"/><integer name="height" value="{}"/><rfilter type="box"/></film>
  </sensor>
  <shape type="rectangle"><transform name="to_world"><rotate x="1" angle="-90"/><scale value="3"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.6, 0.6, 0.6"/></bsdf></shape>
  <shape type="sphere"><point name="center" x="0" y="0.35" z="0"/><float name="radius" value="0.35"/>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.5, 0.4, 0.3"/></bsdf></shape>
  <shape type="sphere"><point name="center" x="0.6" y="1.6" z="0.2"/><float name="radius" value="0.12"/>
    <emitter type="area"><rgb name="radiance" value="30, 30, 30"/></emitter></shape>
</scene>)",
                     sampler, kSize, kSize);
}

TEST(AdaptiveSampling, StatisticalImageEqualsTheFixedRateImageWithinNoise) {
  SKIP_UNDER_SANITIZERS("AdaptiveSampling.StatisticalSpendsFewerSamplesOnFlatRegionsThanOnTheEdge");
  uint64_t adaptive_samples = 0;
  const test::Estimate fixed = test::EstimatedBlocks(
      [&](int seed) { return test::Blocks(Render(NoisyScene(SamplerXml("sobol", 64, seed))).image); });
  const test::Estimate adaptive = test::EstimatedBlocks([&](int seed) {
    const Rendered r = Render(NoisyScene(SamplerXml("sobol", 256, 100 + seed, Statistical(0.05, 16))));
    adaptive_samples += r.stats.samples;
    return test::Blocks(r.image);
  });
  double diff = 0, var = 0, total = 0;
  for (size_t k = 0; k < fixed.mean.size(); ++k)
    diff += adaptive.mean[k] - fixed.mean[k], var += adaptive.var[k] + fixed.var[k], total += fixed.mean[k];
  std::printf("adaptive - fixed: %.3g%% of the image, its standard error %.3g%%; adaptive samples %.1f per pixel\n",
              100 * diff / total, 100 * std::sqrt(var) / total, double(adaptive_samples) / (8.0 * kSize * kSize));
  test::ExpectSameImage(fixed, adaptive, 0.02, "statistical adaptive against 64 spp");
}

TEST(AdaptiveSampling, StatisticalIsTheSameOnAnyThreadCountAndTiling) {
  const std::string xml = NoisyScene(SamplerXml("sobol", 128, 3, Statistical(0.05, 8)));
  const Rendered one = Render(xml, 1, 16), many = Render(xml, 4, 5);
  EXPECT_EQ(one.counts, many.counts);
  ASSERT_EQ(one.image.pixels.size(), many.image.pixels.size());
  for (size_t i = 0; i < one.image.pixels.size(); ++i) ASSERT_EQ(one.image.pixels[i], many.image.pixels[i]) << i;
}

// Passes (as --time-limit and --noise-target take them) and stops (checkpoints) do not move
// where a pixel stops: the rule looks at fixed counts only. A noise target never reached takes
// the samples in passes of 1, 1, 2, 4, ...; the film ends bit for bit as one pass's.
TEST(AdaptiveSampling, StatisticalIsTheSameTakenInPasses) {
  const std::string xml = NoisyScene(SamplerXml("sobol", 96, 5, Statistical(0.05, 8)));
  const Rendered whole = Render(xml);
  RenderSetup setup = LoadSceneFromString(xml, "test.xml", {});
  std::unique_ptr<Sampler> sampler = MakeSampler(setup.sampler);
  Film film(setup.film.width, setup.film.height, setup.film.crop, setup.film.filter);
  ProgressiveOptions po;
  po.render.spp_end = sampler->spp();
  po.noise_target = 1e-9;
  const ProgressiveResult result = RenderProgressive(*setup.camera, *setup.integrator, *sampler, film, po);
  EXPECT_EQ(result.end, RenderEnd::kComplete);
  EXPECT_EQ(result.stats.pixels_completed, result.stats.pixels);
  const Image passes = film.ToImage(*setup.film.color_space);
  for (size_t i = 0; i < passes.pixels.size(); ++i) ASSERT_EQ(passes.pixels[i], whole.image.pixels[i]) << i;
  for (int i = 0; i < kSize * kSize; ++i) ASSERT_EQ(film.SampleCount(Vec2i(i % kSize, i / kSize)), whole.counts[i]) << i;
}

// ---- classic (whitted) adaptive supersampling ------------------------------------------------

std::string Whitted(int depth, double threshold = 0.1) {
  return fmt::format(R"(<string name="adaptive" value="whitted"/><integer name="adaptive_max_depth" value="{}"/>)"
                     R"(<float name="adaptive_threshold" value="{}"/>)",
                     depth, threshold);
}

TEST(AdaptiveSampling, WhittedSubdividesAtTheEdgeOnly) {
  const Regions regions = Classify();
  const Rendered r = Render(EdgeScene("whitted", "<sampler type=\"sobol\">" + Whitted(3) + "</sampler>"));
  const double lit = MeanCount(r.counts, regions.flat_lit), dark = MeanCount(r.counts, regions.flat_dark),
               edge = MeanCount(r.counts, regions.edge);
  std::printf("whitted depth 3: samples per pixel flat lit %.1f, flat dark %.1f, edge %.1f (5 to 145)\n", lit, dark,
              edge);
  EXPECT_EQ(dark, 5);
  EXPECT_EQ(lit, 5);
  EXPECT_GT(edge, 20);
  // The corners and centres of every square of depth 3, (2^3 + 1)^2 + 4^3, and no more.
  EXPECT_EQ(WhittedMaxSamples(3), 145);
  uint32_t most = 0;
  for (uint32_t n : r.counts) {
    EXPECT_GE(n, 5u);
    most = std::max(most, n);
  }
  EXPECT_LE(most, 145u);
}

// Deeper subdivision traces the edge more finely: the edge pixels' coverage error against a
// converged render falls with depth (depth 0, a fixed pattern of 5, is the baseline). A pixel's
// samples share one wavelength sample, whose spectral noise is no error of the placement: the
// coverage is the pixel over the same pixel fully lit (same seed, so same wavelengths).
TEST(AdaptiveSampling, WhittedComesCloserToTheConvergedImageWithDepth) {
  const Regions regions = Classify();
  const std::string ref_sampler = SamplerXml("stratified", 1024, 7);
  const Image ref = Render(EdgeScene("whitted", ref_sampler)).image;
  const Image ref_full = Render(EdgeScene("whitted", ref_sampler, true)).image;
  auto rms = [&](int depth) {
    const std::string sampler = "<sampler type=\"sobol\">" + Whitted(depth) + "</sampler>";
    const Image img = Render(EdgeScene("whitted", sampler)).image;
    const Image full = Render(EdgeScene("whitted", sampler, true)).image;
    double s = 0;
    for (int i : regions.edge) {
      const int x = i % kSize, y = i / kSize;
      const double d = Luminance(img, x, y) / Luminance(full, x, y) - Luminance(ref, x, y) / Luminance(ref_full, x, y);
      s += d * d;
    }
    return std::sqrt(s / double(regions.edge.size()));
  };
  const double e0 = rms(0), e2 = rms(2), e4 = rms(4);
  std::printf("whitted: edge pixels' RMS coverage error against 1024 spp: depth 0 %.4f, depth 2 %.4f, depth 4 %.4f\n",
              e0, e2, e4);
  EXPECT_LT(e2, 0.6 * e0);
  EXPECT_LT(e4, 0.6 * e2);
}

// ---- the loader ------------------------------------------------------------------------------

TEST(AdaptiveSampling, LoaderReadsPatternsAndRefusesWhittedWithAPattern) {
  RenderSetup s = LoadSceneFromString(EdgeScene("path", SamplerXml("rgss", 8, 0, Statistical(0.03, 12))), "t.xml", {});
  EXPECT_EQ(s.sampler.pattern, PixelPattern::kRgss);
  EXPECT_EQ(s.sampler.kind, SamplerKind::kSobol);
  EXPECT_EQ(s.sampler.adaptive.mode, AdaptiveMode::kStatistical);
  EXPECT_DOUBLE_EQ(s.sampler.adaptive.threshold, 0.03);
  EXPECT_EQ(s.sampler.adaptive.min_samples, 12);
  EXPECT_EQ(DescribeSampling(s.sampler), "pattern rgss; adaptive statistical, threshold 0.03, min 12, floor 0.01");
  EXPECT_THROW(LoadSceneFromString(EdgeScene("path", "<sampler type=\"grid\">" + Whitted(2) + "</sampler>"), "t.xml", {}),
               InputError);
  EXPECT_THROW(LoadSceneFromString(EdgeScene("path", R"(<sampler type="sobol"><string name="adaptive" value="often"/></sampler>)"),
                                   "t.xml", {}),
               InputError);
}

}  // namespace
}  // namespace objektiv
