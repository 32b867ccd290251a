#include "render/progressive_render.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

#include "render/noise_estimate.h"

namespace objektiv {

namespace {
using Clock = std::chrono::steady_clock;

// The ends of the passes over [begin, end).
std::vector<int> PassEnds(int begin, int end, bool progressive) {
  std::vector<int> ends;
  if (!progressive) return {end};
  int size = 1;
  for (int s = begin; s < end;) {
    s = std::min(end, s + size);
    ends.push_back(s);
    if (ends.size() > 1) size = std::min(64, 2 * size);
  }
  return ends;
}

// Raises `stop` when a checkpoint or the time limit is due or Ctrl-C came, polling every 10 ms.
class StopWatcher {
 public:
  StopWatcher(std::atomic<bool>& stop, const std::atomic<bool>* interrupt, std::function<bool()> due)
      : stop_(stop), interrupt_(interrupt), due_(std::move(due)), thread_([this] { Run(); }) {}
  ~StopWatcher() {
    {
      std::lock_guard lock(mutex_);
      quit_ = true;
    }
    cv_.notify_one();
    thread_.join();
  }

 private:
  void Run() {
    std::unique_lock lock(mutex_);
    while (!cv_.wait_for(lock, std::chrono::milliseconds(10), [this] { return quit_; }))
      if ((interrupt_ && interrupt_->load()) || due_()) stop_ = true;
  }
  std::atomic<bool>& stop_;
  const std::atomic<bool>* interrupt_;
  std::function<bool()> due_;
  std::mutex mutex_;
  std::condition_variable cv_;
  bool quit_ = false;
  std::thread thread_;
};

void AddStats(RenderStats& to, const RenderStats& s) {
  to.samples += s.samples;
  to.rays += s.rays;
  to.camera_rays_traced += s.camera_rays_traced;
  to.camera_rays_passed += s.camera_rays_passed;
  to.nan_count += s.nan_count;
  to.inf_count += s.inf_count;
  to.skipped_rays += s.skipped_rays;
}
}  // namespace

const char* RenderEndName(RenderEnd end) {
  switch (end) {
    case RenderEnd::kComplete: return "complete";
    case RenderEnd::kNoiseTarget: return "noise target";
    case RenderEnd::kTimeLimit: return "time limit";
    case RenderEnd::kInterrupted: return "interrupted";
  }
  return "?";
}

ProgressiveResult RenderProgressive(const Camera& camera, const Integrator& integrator, const Sampler& sampler,
                                    Film& film, const ProgressiveOptions& options) {
  const RenderOptions& ro = options.render;
  const CropWindow crop = film.crop();
  const auto start = Clock::now();
  auto elapsed = [&] { return options.elapsed_before + std::chrono::duration<double>(Clock::now() - start).count(); };
  const auto period = std::chrono::duration<double>(options.checkpoint_seconds);
  std::atomic<Clock::time_point> next_checkpoint{start + std::chrono::duration_cast<Clock::duration>(period)};
  auto checkpoint_due = [&] { return options.checkpoint_seconds > 0 && Clock::now() >= next_checkpoint.load(); };
  // Every pixel gets its first pass whatever the limit (a black image is no picture).
  std::atomic<bool> first_pass_done{false};
  auto time_up = [&] {
    return options.time_limit_seconds > 0 && first_pass_done && elapsed() >= options.time_limit_seconds;
  };

  Progress progress("Rendering", film.SamplesLeft(ro.spp_begin, ro.spp_end), ro.progress);

  ProgressiveResult out;
  std::atomic<bool> stop{false};
  StopWatcher watcher(stop, options.interrupt, [&] { return checkpoint_due() || time_up(); });
  const bool progressive = options.time_limit_seconds > 0 || options.noise_target > 0;
  bool ended = false;
  for (int pass_end : PassEnds(ro.spp_begin, ro.spp_end, progressive)) {
    for (;;) {
      if (time_up()) {
        out.end = RenderEnd::kTimeLimit;
        ended = true;
        break;
      }
      RenderOptions pass = ro;
      pass.spp_end = pass_end;
      pass.progress_bar = &progress;
      pass.stop = &stop;
      AddStats(out.stats, Render(camera, integrator, sampler, film, pass));
      if (!stop) break;  // the pass is done
      stop = false;
      if (options.interrupt && options.interrupt->load()) {
        out.end = RenderEnd::kInterrupted;
        ended = true;
        break;
      }
      if (checkpoint_due()) {
        if (options.checkpoint) options.checkpoint(elapsed());
        ++out.checkpoints;
        next_checkpoint = Clock::now() + std::chrono::duration_cast<Clock::duration>(period);
      }
    }
    if (ended) break;
    first_pass_done = true;
    if (options.noise_target > 0 && pass_end < ro.spp_end) {
      out.noise = RelativeNoise(film);
      if (out.noise <= options.noise_target) {
        out.end = RenderEnd::kNoiseTarget;
        break;
      }
    }
  }
  progress.Done();
  if (out.end == RenderEnd::kComplete && options.noise_target > 0) out.noise = RelativeNoise(film);
  out.stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  out.elapsed = elapsed();
  out.stats.spp = ro.spp_end - ro.spp_begin;
  out.stats.width = crop.Width(), out.stats.height = crop.Height();
  out.stats.pixels = uint64_t(crop.Width()) * crop.Height();
  out.stats.pixels_completed = PixelsDone(film, sampler, ro.spp_end);
  if (out.end == RenderEnd::kInterrupted && options.checkpoint) {
    options.checkpoint(out.elapsed);
    ++out.checkpoints;
  }
  return out;
}

}  // namespace objektiv
