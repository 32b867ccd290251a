#include "render/renderer.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <stdexcept>

#include "base/progress.h"

namespace objektiv {

void WholeImageIntegrator::RenderBlock(BlockContext&) const {
  throw std::logic_error("an integrator of whole-image passes was handed a block");
}

RenderStats Render(const Camera& camera, const Integrator& integrator, const Sampler& sampler, Film& film,
                   const RenderOptions& options) {
  const CropWindow crop = film.crop();
  const int ts = options.tile_size;
  const int tiles_x = (crop.Width() + ts - 1) / ts, tiles_y = (crop.Height() + ts - 1) / ts;
  const int spp = options.spp_end - options.spp_begin;
  const int64_t pixel_samples_left = film.SamplesLeft(options.spp_begin, options.spp_end);  // the work

  std::unique_ptr<tbb::global_control> limit;
  if (options.threads > 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, options.threads);
  if (const auto* whole = dynamic_cast<const WholeImageIntegrator*>(&integrator))
    return whole->RenderImage(camera, sampler, film, options);

  tbb::enumerable_thread_specific<RenderCounters> counters;
  const bool whole = sampler.adaptive().mode == AdaptiveMode::kWhitted;
  std::optional<Progress> own_progress;
  Progress* progress = options.progress_bar;
  if (!progress) progress = &own_progress.emplace("Rendering", pixel_samples_left, options.progress);
  auto start = std::chrono::steady_clock::now();
  const uint64_t skipped_before = integrator.scene().SkippedRays();

  tbb::parallel_for(0, tiles_x * tiles_y, [&](int tile) {
    PixelBlock block;
    block.p0 = Vec2i(crop.x0 + (tile % tiles_x) * ts, crop.y0 + (tile / tiles_x) * ts);
    block.p1 = Vec2i(std::min(block.p0.x + ts, crop.x1), std::min(block.p0.y + ts, crop.y1));
    block.sample_begin = options.spp_begin;
    block.sample_end = options.spp_end;
    RenderCounters& c = counters.local();
    // Progress in samples; a whitted-adaptive pixel (one "sample index" for all of its
    // samples: Film::SamplesLeft counts it once) in pixels.
    const uint64_t before = whole ? c.whole_pixels : c.samples;
    BlockContext ctx(block, camera, sampler, film, c, options.stop);
    integrator.RenderBlock(ctx);
    progress->Update(int64_t((whole ? c.whole_pixels : c.samples) - before));
  });
  if (own_progress) own_progress->Done();

  RenderStats stats;
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stats.spp = spp;
  stats.width = crop.Width();
  stats.height = crop.Height();
  stats.pixels = uint64_t(crop.Width()) * crop.Height();
  stats.skipped_rays = integrator.scene().SkippedRays() - skipped_before;
  stats.pixels_completed = PixelsDone(film, sampler, options.spp_end);
  for (const RenderCounters& c : counters) {
    stats.samples += c.samples;
    stats.rays += c.rays.closest + c.rays.shadow;
    stats.camera_rays_traced += c.camera.traced;
    stats.camera_rays_passed += c.camera.passed;
    stats.nan_count += c.nan;
    stats.inf_count += c.inf;
  }
  return stats;
}

}  // namespace objektiv
