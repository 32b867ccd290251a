// Renders an image: the crop window in tiles over TBB, each tile a block of work for the
// integrator (render/block_context.h); progress, the stop flag and statistics are kept here.
#pragma once
#include <optional>
#include <atomic>
#include <cstdint>
#include <memory>

#include "base/progress.h"
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
  // Pixels of the crop window, and those that have all their samples (fewer when stopped).
  uint64_t pixels = 0, pixels_completed = 0;
  bool Partial() const { return pixels_completed < pixels; }
  uint64_t skipped_rays = 0;  // rays Embree could not take (see Scene::SkippedRays)
  double SamplesPerSecond() const { return seconds > 0 ? samples / seconds : 0; }
  double MraysPerSecond() const { return seconds > 0 ? rays / seconds * 1e-6 : 0; }
  // Camera rays that came out of the lens per camera ray traced (1 for ideal cameras).
  // The fraction of camera rays traced through a lens that came out of its front; none where
  // no ray was traced through a lens (an ideal camera, or a film that sees no lens at all).
  std::optional<double> CameraPassRate() const {
    if (camera_rays_traced == 0) return std::nullopt;
    return double(camera_rays_passed) / camera_rays_traced;
  }
};

struct RenderOptions {
  // Sample index range [begin, end): each pixel takes those of its indices it does not have
  // yet (Film::NextSample on), so that rendering a range again after a stop goes on where it
  // stopped, and ranges rendered one after another add up.
  int spp_begin = 0, spp_end = 0;
  int threads = 0;  // 0: all cores
  bool progress = false;
  Progress* progress_bar = nullptr;  // updated with the pixel samples taken, if given (else one of its own)
  int tile_size = 16;
  // When this turns true, no pixel is started any more: each thread finishes the pixels it is
  // on (all their samples: a pixel, or the few whose samples share a batch of camera rays);
  // the pixels not started keep what they had.
  const std::atomic<bool>* stop = nullptr;
};

// Integrators whose passes span the whole image (SPPM: a photon pass between camera passes)
// cannot work in blocks: Render hands them the whole sample range at once. Their sample indices
// are iterations of one render: they start at 0 and are taken all together (no parts, no pauses).
class WholeImageIntegrator : public Integrator {
 public:
  using Integrator::Integrator;
  // Renders the iterations [options.spp_begin, options.spp_end) (spp_begin must be 0) into the
  // film; stops after an iteration once options.stop turns true (the pixels then count the
  // iterations done). Threads and progress as for Render.
  virtual RenderStats RenderImage(const Camera& camera, const Sampler& sampler, Film& film,
                                  const RenderOptions& options) const = 0;
  // Never called: Render sends such an integrator to RenderImage.
  void RenderBlock(BlockContext&) const final;
};

RenderStats Render(const Camera& camera, const Integrator& integrator, const Sampler& sampler, Film& film,
                   const RenderOptions& options);

}  // namespace objektiv
