// A render that may stop before its last sample and go on later: the samples in passes over
// the whole image, pauses for checkpoints, a time limit, a noise target and Ctrl-C, all on top
// of Render (render/renderer.h), whose pixels are each taken whole or not at all.
//
// Passes: with a time limit or a noise target, the sample range [begin, end) is taken in
// passes of 1, 1, 2, 4, ... samples per pixel, at most 64 (so that every pixel's noise falls
// alike and the image is whole at every pass's end); otherwise in one pass. A pause (the
// checkpoint's period has run out) lets every thread finish its pixel, calls `checkpoint`
// with the film holding whole pixels only, and goes on with the same pass: the pixels that
// have their samples are skipped (Film::NextSample). The film's sums are exact
// (base/exact_sum.h), so how the samples were grouped into passes, pauses and processes does
// not change the image: stopped, written, read back and resumed, it ends bit for bit as if
// never stopped.
#pragma once
#include <atomic>
#include <functional>

#include "render/renderer.h"

namespace objektiv {

struct ProgressiveOptions {
  RenderOptions render;           // the whole sample range, threads, progress, tiles (its stop is ignored)
  const std::atomic<bool>* interrupt = nullptr;  // Ctrl-C: stop now (with a checkpoint, if any)
  double checkpoint_seconds = 0;  // 0: none; else pause every so often and call checkpoint
  std::function<void(double elapsed_seconds)> checkpoint;
  double time_limit_seconds = 0;  // 0: none; counted from elapsed_before on, once the first pass is done
  double noise_target = 0;        // 0: none; see render/noise_estimate.h
  double elapsed_before = 0;      // rendering seconds of the runs this one resumes
};

enum class RenderEnd {
  kComplete,     // every pixel has every sample of the range
  kNoiseTarget,  // stopped at a pass's end, the noise at or below the target
  kTimeLimit,    // stopped when the time ran out (the pixels of the last pass done have one more pass)
  kInterrupted,  // Ctrl-C
};
const char* RenderEndName(RenderEnd end);

struct ProgressiveResult {
  RenderStats stats;        // of this run (seconds: this run's), pixels_completed of the whole range
  RenderEnd end = RenderEnd::kComplete;
  double elapsed = 0;       // rendering seconds in all, elapsed_before included
  double noise = -1;        // the last noise estimate (-1: none made)
  int checkpoints = 0;
};

ProgressiveResult RenderProgressive(const Camera& camera, const Integrator& integrator, const Sampler& sampler,
                                    Film& film, const ProgressiveOptions& options);

}  // namespace objektiv
