// The viewer's session (app/view/view_session.h) on a thread of its own beside the window: the
// window posts changes, which run on that thread before its next frame (a pass under way
// stops early for them), and takes the latest picture and state when it draws. The scene's
// files are polled for changes twice a second and read again (view_session.h: ReloadIfChanged).
#pragma once
#include <atomic>
#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "io/svg.h"
#include "app/view/view_session.h"

namespace objektiv {

// What the window shows of the session, copied out after each frame or change.
struct ViewSnapshot {
  uint64_t generation = 0;  // grows with each copy
  DisplayImage display;
  ViewProgress progress;
  CameraPose pose;
  std::shared_ptr<const SensorOverrides> sensor;  // the sensor's values as they stand
  std::string sensor_type;
  double exposure = 0;
  ViewLayer layer = ViewLayer::kSum;
  bool has_layers = false;
  std::string lens_name;  // the realistic camera's lens, "" for the others
  // The realistic camera's lens as set up (stopped down, focused) in cross-section with its
  // ray fans (io/lens_plot.h: what `objektiv lens plot` draws); null for the others.
  std::shared_ptr<const Svg> lens_plot;
  std::string error;      // the last change's or reload's that failed ("" when none since)
  std::string notice;     // the last event worth saying (saved a file, read the scene again), until a change
};

// The session's state into `out` (generation + 1), the lens plot made again where the camera
// is not `plotted` (then set to it); error and notice left as they are.
void TakeSnapshot(const ViewSession& session, ViewSnapshot& out, const Camera*& plotted);

class ViewWorker {
 public:
  explicit ViewWorker(std::unique_ptr<ViewSession> session);
  ~ViewWorker();  // stops the frame under way and joins

  // Runs on the session's thread before its next frame. An InputError it throws becomes the
  // snapshot's error; `notice`, if given, its notice once it ran.
  void Post(std::function<void(ViewSession&)> change, std::string notice = "");
  // The latest snapshot if newer than `have` (then copied into it).
  bool Latest(ViewSnapshot& have) const;

 private:
  void Run();
  // `changed`: changes ran (an error of an earlier one is then forgotten unless `error`).
  void Publish(const std::string& error, const std::string& notice, bool changed);

  std::unique_ptr<ViewSession> session_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::pair<std::function<void(ViewSession&)>, std::string>> changes_;
  std::atomic<bool> stop_frame_{false};
  bool quit_ = false;
  ViewSnapshot latest_;
  const Camera* plotted_ = nullptr;  // the camera latest_.lens_plot shows
  std::thread thread_;
};

}  // namespace objektiv
