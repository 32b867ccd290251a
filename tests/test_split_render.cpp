// Renders split into sample ranges, stopped and resumed, and stopped by a noise target or a
// time limit (render/film.h's exact sums, render/progressive_render.h, io/render_part.h).
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "io/render_part.h"
#include "io/scene_loader.h"
#include "render/noise_estimate.h"
#include "render/progressive_render.h"

namespace objektiv {
namespace {

// Diffuse sphere on a floor under a sky: every pixel noisy, some dark.
std::string Scene(int spp, int res) {
  return R"(<scene version="3.0.0">
  <integrator type="path"><integer name="max_depth" value="4"/></integrator>
  <sensor type="perspective"><float name="fov" value="40"/>
    <transform name="to_world"><lookat origin="0, 1, 3.5" target="0, 1, 0" up="0, 1, 0"/></transform>
    <sampler type="sobol"><integer name="sample_count" value=")" +
         std::to_string(spp) + R"("/></sampler>
    <film type="hdrfilm"><integer name="width" value=")" +
         std::to_string(res) + R"("/><integer name="height" value=")" + std::to_string(res) + R"("/>
      <rfilter type="gaussian"/></film></sensor>
  <emitter type="constant"><rgb name="radiance" value="0.5, 0.6, 0.7"/></emitter>
  <shape type="sphere"><point name="center" value="0, 1, 0"/><float name="radius" value="0.5"/></shape>
  <shape type="rectangle"><transform name="to_world"><rotate x="1" angle="-90"/><scale value="3"/></transform></shape>
</scene>)";
}

struct SplitSetup {
  RenderSetup s;
  std::unique_ptr<Sampler> sampler;
  explicit SplitSetup(int spp, int res = 24) : s(LoadSceneFromString(Scene(spp, res), "split.xml", {})), sampler(MakeSampler(s.sampler)) {}
  Film NewFilm() const { return Film(s.film.width, s.film.height, s.film.crop, s.film.filter); }
  void RenderRange(Film& film, int begin, int end) const {
    RenderOptions opt;
    opt.spp_begin = begin, opt.spp_end = end, opt.threads = 2;
    Render(*s.camera, *s.integrator, *sampler, film, opt);
  }
};

bool SameBits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

// Ranges rendered apart and merged give the unsplit film's image bit for bit, although their
// sums were grouped otherwise (the doubles of the sums differ: plain double sums would not merge
// exactly).
TEST(SplitRender, SampleRangesMergeBitForBit) {
  SplitSetup t(16);
  Film whole = t.NewFilm();
  t.RenderRange(whole, 0, 16);
  Film a = t.NewFilm(), b = t.NewFilm(), c = t.NewFilm();
  t.RenderRange(a, 0, 5);
  b.StartSamplesAt(5);
  t.RenderRange(b, 5, 11);
  c.StartSamplesAt(11);
  t.RenderRange(c, 11, 16);
  Film merged = t.NewFilm();
  for (const Film* f : {&c, &a, &b}) merged.AddAccumulators(f->Accumulators());
  EXPECT_TRUE(SameBits(merged.Xyz(), whole.Xyz()));
  EXPECT_EQ(merged.samples_per_pixel(), 16);
  const FilmAccumulators ma = merged.Accumulators(), wa = whole.Accumulators();
  int grouped_otherwise = 0;
  for (size_t i = 0; i < ma.sums.size(); ++i) grouped_otherwise += ma.sums[i].hi != wa.sums[i].hi || ma.sums[i].lo != wa.sums[i].lo;
  EXPECT_GT(grouped_otherwise, 0) << "every sum came out the same: the test shows nothing";
  // A film of other planes is refused.
  Film other = t.NewFilm();
  other.KeepEmitted();
  EXPECT_THROW(merged.AddAccumulators(other.Accumulators()), std::invalid_argument);
}

// The part file keeps the sums exactly: written, read back and merged, bit for bit.
TEST(SplitRender, PartFilesKeepTheSumsExactly) {
  SplitSetup t(8, 150);
  Film whole = t.NewFilm(), a = t.NewFilm(), b = t.NewFilm();  // 150 rows: strips of 64, 64 and 22
  t.RenderRange(whole, 0, 8);
  t.RenderRange(a, 0, 3);
  b.StartSamplesAt(3);
  t.RenderRange(b, 3, 8);
  const std::string dir = ::testing::TempDir();
  RenderPartInfo info;
  info.version = "test", info.scene = "split.xml", info.scene_hash = "0", info.defines = "{}";
  info.spp = 8, info.seed = 1ull << 40, info.width = info.height = 150;
  info.render_crop = info.crop = t.s.film.crop;
  Film merged = t.NewFilm(), merged_by_strips = t.NewFilm();
  int k = 0;
  for (const auto& [film, begin, end] : {std::tuple(&a, 0, 3), std::tuple(&b, 3, 8)}) {
    info.spp_begin = begin, info.spp_end = end, info.pixels_completed = 150 * 150;
    const std::string path = dir + "/part" + std::to_string(k++) + ".exr";
    WriteRenderPart(path, film->ToImage(ColorSpace::Rec709()), *film, info);
    const RenderPart read = ReadRenderPart(path);
    EXPECT_EQ(read.info.Mismatch(info), "");
    EXPECT_EQ(read.info.seed, 1ull << 40);
    EXPECT_EQ(read.acc.first_sample, begin);
    merged.AddAccumulators(read.acc);
    AddRenderPart(path, merged_by_strips);
  }
  EXPECT_TRUE(SameBits(merged.Xyz(), whole.Xyz()));
  EXPECT_TRUE(SameBits(merged_by_strips.Xyz(), whole.Xyz()));
}

// Paused for checkpoints every few milliseconds, the film holds whole pixels only (each has all
// of the pass's samples or none of them), and the render ends as one never paused.
TEST(SplitRender, CheckpointsHoldWholePixelsAndChangeNothing) {
  SplitSetup t(64, 64);  // about 0.15 s on 2 cores: some 10 pauses (the watcher looks every 10 ms)
  Film plain = t.NewFilm();
  t.RenderRange(plain, 0, 64);
  Film film = t.NewFilm();
  ProgressiveOptions po;
  po.render.spp_begin = 0, po.render.spp_end = 64, po.render.threads = 2;
  po.checkpoint_seconds = 0.003;
  int bad = 0, paused = 0;
  po.checkpoint = [&](double) {
    const FilmAccumulators acc = film.Accumulators();
    for (uint32_t n : acc.counts) bad += n != 0 && n != 64;
    ++paused;
  };
  const ProgressiveResult r = RenderProgressive(*t.s.camera, *t.s.integrator, *t.sampler, film, po);
  EXPECT_EQ(r.end, RenderEnd::kComplete);
  EXPECT_GE(paused, 2);
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(r.stats.pixels_completed, 64u * 64u);
  EXPECT_TRUE(SameBits(film.Xyz(), plain.Xyz()));
}

// The noise estimate falls as 1/sqrt(spp), and a noise target stops the render at the first
// pass's end at or below it, before the last sample.
TEST(SplitRender, NoiseTargetStopsWhereTheNoiseIsReached) {
  SplitSetup t(1024);
  Film f16 = t.NewFilm(), f64 = t.NewFilm();
  t.RenderRange(f16, 0, 16);
  t.RenderRange(f64, 0, 64);
  const double n16 = RelativeNoise(f16), n64 = RelativeNoise(f64);
  EXPECT_NEAR(n16 / n64, 2.0, 0.4) << n16 << " " << n64;
  Film film = t.NewFilm();
  ProgressiveOptions po;
  po.render.spp_begin = 0, po.render.spp_end = 1024, po.render.threads = 2;
  po.noise_target = n64;
  const ProgressiveResult r = RenderProgressive(*t.s.camera, *t.s.integrator, *t.sampler, film, po);
  EXPECT_EQ(r.end, RenderEnd::kNoiseTarget);
  EXPECT_LE(r.noise, n64);
  EXPECT_GE(film.samples_per_pixel(), 32);
  EXPECT_LE(film.samples_per_pixel(), 128);
}

// A time limit stops within a short while of it, every pixel with samples (the passes keep
// the image whole).
TEST(SplitRender, TimeLimitStopsWithEveryPixelStarted) {
  SplitSetup t(1 << 20, 32);
  Film film = t.NewFilm();
  ProgressiveOptions po;
  po.render.spp_begin = 0, po.render.spp_end = 1 << 20, po.render.threads = 2;
  po.time_limit_seconds = 0.5;
  const ProgressiveResult r = RenderProgressive(*t.s.camera, *t.s.integrator, *t.sampler, film, po);
  EXPECT_EQ(r.end, RenderEnd::kTimeLimit);
  EXPECT_LT(r.elapsed, 2.0);
  const FilmAccumulators acc = film.Accumulators();
  for (uint32_t n : acc.counts) ASSERT_GT(n, 0u);
}

}  // namespace
}  // namespace objektiv
