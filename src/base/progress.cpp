#include "base/progress.h"

#include <cstdio>

namespace objektiv {

Progress::Progress(std::string title, int64_t total, bool enabled)
    : title_(std::move(title)), total_(total > 0 ? total : 1), enabled_(enabled),
      start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

Progress::~Progress() { Done(); }

double Progress::ElapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::Update(int64_t delta) {
  done_ += delta;
  if (!enabled_) return;
  auto now = std::chrono::steady_clock::now();
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock() || now - last_draw_ < std::chrono::milliseconds(200)) return;
  last_draw_ = now;
  Draw(false);
}

void Progress::Done() {
  std::lock_guard lock(mutex_);
  if (finished_) return;
  finished_ = true;
  if (enabled_) Draw(true);
}

void Progress::Draw(bool final) {
  double frac = std::min(1.0, double(done_.load()) / total_);
  double elapsed = ElapsedSeconds();
  double remaining = frac > 0 ? elapsed / frac - elapsed : 0;
  const int width = 40;
  int filled = int(frac * width);
  std::string bar(filled, '=');
  bar.resize(width, ' ');
  std::fprintf(stderr, "\r%s [%s] %5.1f%%  %.1fs elapsed, %.1fs left ", title_.c_str(), bar.c_str(), frac * 100,
               elapsed, final ? 0.0 : remaining);
  if (final) std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

}  // namespace objektiv
