#include "app/view/view_worker.h"

#include <chrono>
#include <cmath>

#include <spdlog/spdlog.h>

#include "base/error.h"
#include "camera/realistic_camera.h"
#include "io/lens_plot.h"

namespace objektiv {

namespace {

// The ray fans of the film's centre, 70% of its corner's field and its corner (paraxially: the
// angle whose image lies at the film's radius), within the fields the lens can trace.
std::vector<double> FieldsOf(const RealisticCamera& camera) {
  const LensSystem& lens = camera.lens();
  const double largest = DefaultFields(lens).back();
  const double corner = std::atan(camera.FilmRadius() / std::abs(lens.Paraxial(kLambdad).efl)) * 180 / M_PI;
  const double f = std::min(corner, largest);
  return {0, 0.7 * f, f};
}

}  // namespace

void TakeSnapshot(const ViewSession& s, ViewSnapshot& out, const Camera*& plotted) {
  const auto* real = dynamic_cast<const RealisticCamera*>(&s.camera());
  if (&s.camera() != plotted) {
    out.lens_plot = real ? std::make_shared<const Svg>(PlotLensLayoutAsFocused(real->lens(), FieldsOf(*real))) : nullptr;
    plotted = &s.camera();
  }
  out.generation++;
  out.display = s.display();
  out.progress = s.progress();
  out.pose = s.pose();
  out.sensor = std::make_shared<SensorOverrides>(s.sensor());
  out.sensor_type = s.sensor().type();
  out.exposure = s.exposure();
  out.layer = s.layer();
  out.has_layers = s.HasLensLayers();
  out.lens_name = real ? real->lens().prescription().name : "";
}

ViewWorker::ViewWorker(std::unique_ptr<ViewSession> session) : session_(std::move(session)) {
  Publish("", "", false);
  thread_ = std::thread([this] { Run(); });
}

ViewWorker::~ViewWorker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    quit_ = true;
  }
  stop_frame_ = true;
  wake_.notify_all();
  thread_.join();
}

void ViewWorker::Post(std::function<void(ViewSession&)> change, std::string notice) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    changes_.emplace_back(std::move(change), std::move(notice));
  }
  stop_frame_ = true;
  wake_.notify_all();
}

bool ViewWorker::Latest(ViewSnapshot& have) const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (latest_.generation == have.generation) return false;
  have = latest_;
  return true;
}

void ViewWorker::Publish(const std::string& error, const std::string& notice, bool changed) {
  std::lock_guard<std::mutex> lock(mutex_);
  TakeSnapshot(*session_, latest_, plotted_);
  if (!error.empty() || changed) latest_.error = error;
  if (!notice.empty() || changed) latest_.notice = notice;
}

void ViewWorker::Run() {
  using Clock = std::chrono::steady_clock;
  Clock::time_point polled = Clock::now();
  for (;;) {
    std::deque<std::pair<std::function<void(ViewSession&)>, std::string>> changes;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (quit_) return;
      changes.swap(changes_);
      stop_frame_ = false;
    }
    std::string error, notice;
    bool reloaded = false;
    for (auto& [change, what] : changes) {
      try {
        change(*session_);
        if (!what.empty()) notice = what;
        if (std::string said = session_->TakeNotice(); !said.empty()) notice = said;
      } catch (const InputError& e) {
        error = e.what();
      } catch (const std::exception& e) {
        error = std::string("error: ") + e.what();
      }
    }
    if (Clock::now() - polled > std::chrono::milliseconds(500)) {
      polled = Clock::now();
      if (std::optional<std::string> reload = session_->ReloadIfChanged()) {
        if (reload->empty()) {
          notice = session_->scene_path() + ": read again";
          reloaded = true;  // (an earlier error is over)
        } else {
          error = *reload;
          spdlog::error("{} (the last good scene stays)", error);
        }
      }
    }
    bool worked = false;
    try {
      worked = session_->Step(&stop_frame_);
    } catch (const InputError& e) {
      error = e.what();
    } catch (const std::exception& e) {  // (a bug: said, not a lost session)
      error = std::string("error: ") + e.what();
    }
    if (worked || !changes.empty() || !error.empty() || !notice.empty()) Publish(error, notice, !changes.empty() || reloaded);
    if (!worked) {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait_for(lock, std::chrono::milliseconds(500), [this] { return quit_ || !changes_.empty(); });
    }
  }
}

}  // namespace objektiv
