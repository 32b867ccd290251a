// Renders an image: the crop window in tiles over TBB, each tile a block of work for the
// integrator (render/block_context.h); progress, the stop flag and statistics are kept here.
#pragma once
#include <atomic>
#include <cstdint>
#include <memory>

#include "camera/camera.h"
#include "render/film.h"
#include "render/integrator.h"

namespace objektiv {

struct RenderStats {
  double seconds = 0;
  int spp = 0;
  int width = 0, height = 0;
  uint64_t samples = 0, rays = 0;
  uint64_t camera_rays_traced = 0, camera_rays_passed = 0;  // through a lens (see CameraRayCount)
  uint64_t nan_count = 0, inf_count = 0;
  // Pixels of the crop window, and those that got all their samples (fewer when stopped).
  uint64_t pixels = 0, pixels_completed = 0;
  bool Partial() const { return pixels_completed < pixels; }
  uint64_t skipped_rays = 0;  // rays Embree could not take (see Scene::SkippedRays)
  double SamplesPerSecond() const { return seconds > 0 ? samples / seconds : 0; }
  double MraysPerSecond() const { return seconds > 0 ? rays / seconds * 1e-6 : 0; }
  // Camera rays that came out of the lens per camera ray traced (1 for ideal cameras).
  double CameraPassRate() const { return camera_rays_traced ? double(camera_rays_passed) / camera_rays_traced : 1; }
};

struct RenderOptions {
  int spp_begin = 0, spp_end = 0;  // sample index range [begin, end)
  int threads = 0;                 // 0: all cores
  bool progress = false;
  int tile_size = 16;
  // When this turns true, no pixel is started any more: each thread finishes the pixel it is on
  // (all its samples), the others keep no samples at all (zero on the film).
  const std::atomic<bool>* stop = nullptr;
};

RenderStats Render(const Camera& camera, const Integrator& integrator, const Sampler& sampler, Film& film,
                   const RenderOptions& options);

}  // namespace objektiv
