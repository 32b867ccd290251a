// A progress bar with elapsed and remaining time, drawn on stderr only on a terminal.
#pragma once
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace objektiv {

class Progress {
 public:
  Progress(std::string title, int64_t total, bool enabled);
  ~Progress();
  void Update(int64_t done_delta);
  void Done();
  double ElapsedSeconds() const;

 private:
  void Draw(bool final);
  std::string title_;
  int64_t total_;
  bool enabled_;
  std::atomic<int64_t> done_{0};
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::mutex mutex_;
  bool finished_ = false;
};

}  // namespace objektiv
