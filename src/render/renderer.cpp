#include "render/renderer.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>

#include "base/progress.h"

namespace objektiv {

RenderStats Render(const Camera& camera, const Integrator& integrator, const Sampler& sampler_prototype, Film& film,
                   const RenderOptions& options) {
  const CropWindow crop = film.crop();
  const int ts = options.tile_size;
  const int tiles_x = (crop.Width() + ts - 1) / ts, tiles_y = (crop.Height() + ts - 1) / ts;
  const int spp = options.spp_end - options.spp_begin;

  std::unique_ptr<tbb::global_control> limit;
  if (options.threads > 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, options.threads);

  struct ThreadState {
    std::unique_ptr<Sampler> sampler;
    RayCounts rays;
    uint64_t camera_rays = 0, camera_failed = 0, nan = 0, inf = 0;
  };
  tbb::enumerable_thread_specific<ThreadState> states([&] { return ThreadState{sampler_prototype.Clone()}; });
  Progress progress("Rendering", int64_t(tiles_x) * tiles_y, options.progress);
  auto start = std::chrono::steady_clock::now();

  tbb::parallel_for(0, tiles_x * tiles_y, [&](int tile) {
    ThreadState& st = states.local();
    Sampler& sampler = *st.sampler;
    int tx0 = crop.x0 + (tile % tiles_x) * ts, ty0 = crop.y0 + (tile / tiles_x) * ts;
    int tx1 = std::min(tx0 + ts, crop.x1), ty1 = std::min(ty0 + ts, crop.y1);
    for (int y = ty0; y < ty1; ++y)
      for (int x = tx0; x < tx1; ++x) {
        Vec2i pixel(x, y);
        for (int s = options.spp_begin; s < options.spp_end; ++s) {
          sampler.StartPixelSample(pixel, s);
          FilterSample fs = film.filter().Sample(sampler.GetPixel2D());
          SampledWavelengths lambda = SampledWavelengths::SampleVisible(sampler.Get1D());
          CameraSample cs{Vec2f(x + 0.5f + fs.offset.x, y + 0.5f + fs.offset.y), sampler.Get2D()};
          ++st.camera_rays;
          std::optional<CameraRay> cr = camera.GenerateRay(cs, lambda);
          SampledSpectrum L(0.f);
          if (cr) {
            L = cr->weight * integrator.Li(cr->ray, lambda, sampler, st.rays);
          } else {
            ++st.camera_failed;
          }
          // Non-finite radiance is counted and dropped, never written to the film.
          if (L.HasNaN()) {
            ++st.nan;
            continue;
          }
          if (L.HasInf()) {
            ++st.inf;
            continue;
          }
          film.AddSample(pixel, L, lambda, fs.weight);
        }
      }
    progress.Update(1);
  });
  progress.Done();

  RenderStats stats;
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stats.spp = spp;
  stats.width = crop.Width();
  stats.height = crop.Height();
  stats.samples = uint64_t(spp) * crop.Width() * crop.Height();
  for (const ThreadState& st : states) {
    stats.rays += st.rays.closest + st.rays.shadow;
    stats.camera_rays += st.camera_rays;
    stats.camera_rays_failed += st.camera_failed;
    stats.nan_count += st.nan;
    stats.inf_count += st.inf;
  }
  return stats;
}

}  // namespace objektiv
