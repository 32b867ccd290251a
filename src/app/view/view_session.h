// What the interactive viewer shows and changes, without a window: a scene loaded once, its
// camera moved and built again as the controls change, and the image as it converges.
//
// Each change starts the image again. While the camera moves, frames are a fast preview: one
// sample per pixel of direct light only (render/integrator.h: DirectIntegrator, one emitter
// and one BSDF sample), at a resolution reduced so that a frame takes about 1 / preview_fps
// (the film divided by 1, 2, 3, 4, 6, 8 or 12 each way, chosen from the last frame's time per
// pixel). Once it stands still, one preview frame at full resolution, then passes of the
// scene's own integrator over the whole film, added up (each pass samples n = 1, 1, 2, 4 ...
// per pixel, at most what fits in about a quarter of a second), up to the scene's sample
// count. The passes take the sample indices a render takes, from the same sampler, so the image
// at the scene's sample count is the one `objektiv render` makes of the saved camera
// (app/view/scene_with_camera.h), bit for bit. The lens's ghosts and diffraction
// (render/lens_layers.h), where the sensor asks for them, are composed over the image once the
// passes have run 2 seconds (or reached their end), then again once 4 times the composition's
// time has passed (a change stops them); between, the picture shows the
// film's later passes with the ghosts and diffraction as last composed. A saved image
// composes them anew.
//
// Not thread-safe: one thread changes and steps it (app/view/view_worker.h runs it beside a window).
#pragma once
#include <atomic>
#include <chrono>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/scene_loader.h"
#include "render/lens_layers.h"
#include "app/view/camera_pose.h"
#include "app/view/sensor_overrides.h"

namespace objektiv {

// The picture the viewer shows: sRGB-encoded, 8 bits, RGBA (alpha 255), rows top to bottom,
// quantised as the PNG writer does.
struct DisplayImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;
  uint64_t frame = 0;  // grows with each picture made
};

// The lens's layers (render/lens_layers.h) the picture can show alone.
enum class ViewLayer { kSum, kPrimary, kGhosts, kDiffraction };
const char* ViewLayerName(ViewLayer layer);

struct ViewOptions {
  std::map<std::string, std::string> defines;  // -D name=value, as for render
  int width = 0, height = 0;                    // the film's size instead of the scene's (0: the scene's)
  int max_spp = 0;                              // samples per pixel to stop at (0: the scene's sample count)
  double preview_fps = 30;                      // what the moving preview aims for
  int threads = 0;                              // 0: all cores
};

// How far the image has come, for the panel.
struct ViewProgress {
  bool preview = true;  // showing a preview frame (else the integrator's passes)
  int spp = 0, max_spp = 0;  // samples per pixel of the passes so far, and where they stop
  int width = 0, height = 0;  // of the frame shown (a moving preview's is reduced)
  double frame_seconds = 0;   // the last frame's (a preview frame's, or a pass's)
  std::optional<double> camera_pass_rate;  // of the last frame, through a lens
  bool layers = false;  // the lens's ghosts or diffraction are composed over it
};

class ViewSession {
 public:
  // Loads the scene (InputError on any problem in it).
  ViewSession(const std::string& scene_path, const ViewOptions& options);
  ~ViewSession();

  // --- What the controls change; each starts the image again. ---
  const CameraPose& pose() const { return pose_; }
  // `moving`: the preview at reduced resolution until the camera stands still (SetMoving(false)).
  void SetPose(const CameraPose& pose, bool moving);
  void SetMoving(bool moving);
  // The sensor's properties (app/view/sensor_overrides.h): the camera is built again at once;
  // where it cannot be (a value out of range, an f-number faster than the lens), InputError
  // and the property keeps its value.
  const SensorOverrides& sensor() const { return sensor_; }
  void ChangeSensor(const std::function<void(SensorOverrides&)>& change);
  // The same value again changes nothing; another lens that does not open as far as the
  // f-number set asks is taken wide open (warned, and a notice), and the next lens that does
  // gets that f-number back.
  void SetSensorProperty(const std::string& name, PropertyData value, const std::string& type_name);
  // What the last changes had to say beside errors (a lens taken wide open), once.
  std::string TakeNotice();
  void ResetSensorProperty(const std::string& name) {
    ChangeSensor([&](SensorOverrides& s) { s.Reset(name); });
  }
  // Focuses on what the camera sees at a pixel of the film (continuous coordinates of the
  // full film): the scene point under it, through the middle of the lens. False (nothing
  // changed) where the ray meets nothing or the camera cannot focus (a pinhole).
  bool FocusAt(double x, double y);
  // The scene point the middle of the lens sees through a pixel, if any.
  std::optional<Vec3f> PointAt(double x, double y);
  // Display exposure in stops (the film's `exposure` to begin with); does not restart: the
  // picture shown (a preview's too) is shown again at once.
  double exposure() const { return exposure_; }
  void SetExposure(double stops);
  ViewLayer layer() const { return layer_; }
  void SetLayer(ViewLayer layer);
  bool HasLensLayers() const;  // whether the sensor asks for ghosts or diffraction

  // --- Work. ---
  // One frame: a preview, or a pass of the integrator. False when there is nothing to do (the
  // passes have every sample). `stop` (the window's, when a change arrives) ends a pass early:
  // the pixels begun finish, the others wait for the next.
  // A camera that cannot be built (a lens file broken on disk since it was read): InputError,
  // then nothing (false) until the next change or reload.
  bool Step(const std::atomic<bool>* stop = nullptr);
  const DisplayImage& display() const { return display_; }
  const ViewProgress& progress() const { return progress_; }
  // Passes stop at `spp` samples per pixel (at most the scene's; 0: the scene's).
  void StopPassesAt(int spp) { stop_at_ = spp; }

  // --- Files. ---
  // The image as it stands (the full film's: a preview frame's pixels are not kept) as a
  // linear EXR and the tone-mapped PNG beside it, as `objektiv render` writes them; InputError
  // before the first pass.
  void SaveImage(const std::string& exr_path) const;
  // The scene file with the camera as it is now (app/view/scene_with_camera.h).
  void SaveScene(const std::string& xml_path) const;
  // Reads the scene again if a file it read has changed since (polled, cheap): the pose, the
  // values set and the exposure stay. Empty when nothing changed; "" when read again; else
  // the error, the last good scene staying (tried again when a file changes again).
  std::optional<std::string> ReloadIfChanged();

  const std::string& scene_path() const { return scene_path_; }
  const RenderSetup& setup() const { return setup_; }
  const Camera& camera() const { return *setup_.camera; }
  // The film of the passes (null before the first).
  const Film* film() const { return film_.get(); }

 private:
  void Load();  // (scene_path_, options_) -> doc_, setup_, sensor_ (keeping pose and values set)
  void Restart();
  bool Frame(const std::atomic<bool>* stop);
  // The camera of the passes built again from the node if the pose changed since it was.
  void BuildCameraWhereItStands();
  // `quiet`: no warnings either (a preview's camera: the camera of the passes says them).
  std::unique_ptr<Camera> MakeCamera(const ObjectNode& sensor, int width, int height, bool quiet = false) const;
  const Camera& PreviewCamera(int divisor);
  int PreviewDivisor() const;
  void PreviewFrame(int divisor, const std::atomic<bool>* stop);
  // The lamps' images and ghosts at preview quality (FlareSettings::Preview) into preview_.
  void PreviewFlare(const Camera& camera, const std::atomic<bool>* stop);
  // The last preview frame shown again, composed for the layer now chosen.
  void ShowPreview();
  void Pass(const std::atomic<bool>* stop);
  void ShowFilm();
  void ShowXyz(const std::vector<float>& xyz, int width, int height);

  std::string scene_path_;
  ViewOptions options_;
  SceneDocument doc_;
  RenderSetup setup_;
  SensorOverrides sensor_{nullptr};
  CameraPose pose_;
  double exposure_ = 0, scene_exposure_ = 0;
  bool full_camera_stale_ = false;
  bool scene_cropped_ = false;  // the scene's film has a crop window (the viewer leaves it out)
  std::string stalled_;         // why Step does nothing until the next change
  std::optional<double> wanted_fnumber_;  // the f-number a slower lens could not take
  std::string notice_;  // the pose changed since the camera of the passes was built
  ViewLayer layer_ = ViewLayer::kSum;
  bool moving_ = false;
  int full_width_ = 0, full_height_ = 0;

  std::unique_ptr<Integrator> preview_integrator_;
  std::map<int, std::unique_ptr<Camera>> preview_cameras_;  // by divisor
  double preview_seconds_per_pixel_ = 0;  // the picture's, the lamps' images and ghosts apart
  double preview_flare_seconds_ = 0;      // theirs (the bundles' cost hardly depends on the resolution)
  bool still_preview_shown_ = false;
  // The last preview frame's parts, composed for the layer chosen (ShowPreview): the picture,
  // the lamps' images and their ghosts (XYZ; the last two empty where the lens has no effects).
  struct PreviewParts {
    int width = 0, height = 0;
    std::vector<float> picture, lights, ghosts;
  } preview_;

  std::unique_ptr<Film> film_;
  std::unique_ptr<Sampler> sampler_;
  int spp_done_ = 0;
  int stop_at_ = 0;
  double pass_seconds_per_spp_ = 0;
  std::optional<LensLayers> layers_;
  std::vector<float> layers_film_;  // the film's XYZ the layers were composed with
  double layers_seconds_ = 0;  // the last composition's time
  std::chrono::steady_clock::time_point layers_time_, restarted_;

  DisplayImage display_;
  std::vector<float> shown_xyz_;  // the picture shown, before the exposure and the tone curve
  ViewProgress progress_;
  std::map<std::string, std::filesystem::file_time_type> watched_;
};

}  // namespace objektiv
