#include "render/renderer.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>

#include "base/progress.h"

namespace objektiv {

namespace {
constexpr int kCameraBatch = 64;  // samples of one pixel whose camera rays are made together
}  // namespace

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
    std::vector<Sampler> samplers;
    std::vector<FilterSample> filter_samples;
    std::vector<SampledWavelengths> lambdas;
    std::vector<CameraSample> camera_samples;
    std::vector<std::optional<CameraRay>> rays_out;
    std::vector<const Ray*> first_rays;
    std::vector<std::optional<SurfaceInteraction>> first_hits;
    RayCounts rays;
    CameraRayCount camera;
    uint64_t nan = 0, inf = 0;
    uint64_t pixels = 0;  // completed
  };
  tbb::enumerable_thread_specific<ThreadState> states([&] {
    ThreadState st;
    st.samplers.assign(kCameraBatch, sampler_prototype);
    st.filter_samples.resize(kCameraBatch);
    st.lambdas.resize(kCameraBatch);
    st.camera_samples.resize(kCameraBatch);
    st.rays_out.resize(kCameraBatch);
    st.first_rays.resize(kCameraBatch);
    st.first_hits.resize(kCameraBatch);
    return st;
  });
  const bool lens_sample = camera.UsesLensSample();
  Progress progress("Rendering", int64_t(tiles_x) * tiles_y, options.progress);
  auto start = std::chrono::steady_clock::now();
  const uint64_t skipped_before = integrator.scene().SkippedRays();

  auto stopped = [&] { return options.stop && options.stop->load(std::memory_order_relaxed); };

  tbb::parallel_for(0, tiles_x * tiles_y, [&](int tile) {
    ThreadState& st = states.local();
    int tx0 = crop.x0 + (tile % tiles_x) * ts, ty0 = crop.y0 + (tile / tiles_x) * ts;
    int tx1 = std::min(tx0 + ts, crop.x1), ty1 = std::min(ty0 + ts, crop.y1);
    for (int y = ty0; y < ty1; ++y)
      for (int x = tx0; x < tx1; ++x) {
        if (stopped()) return;
        Vec2i pixel(x, y);
        // Camera rays for a group of samples at once (a lens traces them faster together);
        // each sample's sampler state is kept so that its path goes on where it left off.
        for (int s0 = options.spp_begin; s0 < options.spp_end; s0 += kCameraBatch) {
          const int n = std::min(kCameraBatch, options.spp_end - s0);
          for (int k = 0; k < n; ++k) {
            Sampler& sk = st.samplers[k];
            sk.StartPixelSample(pixel, s0 + k);
            st.filter_samples[k] = film.filter().Sample(sk.GetPixel2D());
            st.lambdas[k] = SampledWavelengths::SampleVisible(sk.Get1D());
            Vec2f offset = st.filter_samples[k].offset;
            Vec2f lens = lens_sample ? sk.Get2D() : Vec2f(0.5f, 0.5f);
            st.camera_samples[k] = {Vec2f(x + 0.5f + offset.x, y + 0.5f + offset.y), lens};
          }
          camera.GenerateRays(std::span(st.camera_samples.data(), n), std::span(st.lambdas.data(), n),
                              std::span(st.rays_out.data(), n), st.camera);
          // The camera rays' first hits, traced together (they are coherent: packets pay).
          for (int k = 0; k < n; ++k) {
            st.first_rays[k] = st.rays_out[k] ? &st.rays_out[k]->ray : nullptr;
            st.rays.closest += st.rays_out[k].has_value();
          }
          integrator.scene().IntersectCoherent(std::span(st.first_rays.data(), n), std::span(st.first_hits.data(), n));
          for (int k = 0; k < n; ++k) {
            SampledWavelengths& lambda = st.lambdas[k];
            const std::optional<CameraRay>& cr = st.rays_out[k];
            SampledSpectrum L(0.f);
            if (cr) L = cr->weight * integrator.Li(cr->ray, st.first_hits[k], lambda, st.samplers[k], st.rays);
            // Non-finite radiance is counted and dropped, never written to the film.
            if (L.HasNaN()) {
              ++st.nan;
              continue;
            }
            if (L.HasInf()) {
              ++st.inf;
              continue;
            }
            film.AddSample(pixel, L, lambda, st.filter_samples[k].weight);
          }
        }
        ++st.pixels;
      }
    progress.Update(1);
  });
  progress.Done();

  RenderStats stats;
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stats.spp = spp;
  stats.width = crop.Width();
  stats.height = crop.Height();
  stats.pixels = uint64_t(crop.Width()) * crop.Height();
  stats.skipped_rays = integrator.scene().SkippedRays() - skipped_before;
  for (const ThreadState& st : states) {
    stats.pixels_completed += st.pixels;
    stats.rays += st.rays.closest + st.rays.shadow;
    stats.camera_rays_traced += st.camera.traced;
    stats.camera_rays_passed += st.camera.passed;
    stats.nan_count += st.nan;
    stats.inf_count += st.inf;
  }
  stats.samples = uint64_t(spp) * stats.pixels_completed;
  return stats;
}

}  // namespace objektiv
