// The viewer's panel (Dear ImGui): what the image shows (samples per pixel, frames per second,
// the camera's pass rate), the lens and its settings (focus, f-number, blades, dispersion,
// vignetting, ghosts, diffraction), the exposure and the layer shown, saving the image and the
// camera, and the lens in cross-section with its ray fans. Each change is posted to the
// session's thread (app/view/view_worker.h).
#pragma once
#include <string>
#include <vector>

#include "app/view/view_worker.h"

namespace objektiv {

class ViewPanel {
 public:
  explicit ViewPanel(const std::string& scene_path);
  // Draws the panel in the window's rectangle (x, y, width, height) from the latest snapshot;
  // `fps`: pictures shown per second. Without a worker (a scripted run) the controls only show.
  void Draw(const ViewSnapshot& s, ViewWorker* worker, float x, float y, float width, float height, double fps);
  // Saves the image and the camera to the panel's file names (ctrl + S).
  void SaveBoth(ViewWorker& worker) const;

 private:
  void LensControls(const ViewSnapshot& s, ViewWorker* worker);
  void Files(ViewWorker* worker);
  std::vector<std::string> lenses_;  // the shipped lenses, for the lens menu
  std::string lens_file_, image_path_, camera_path_;
};

}  // namespace objektiv
