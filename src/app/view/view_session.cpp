#include "app/view/view_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <spdlog/spdlog.h>

#include "app/render_finish.h"
#include "base/error.h"
#include "base/input_files.h"
#include "camera/realistic_camera.h"
#include "camera/stereo_camera.h"
#include "io/tonemap.h"
#include "render/integrator.h"
#include "render/lens_flare.h"
#include "render/renderer.h"
#include "app/view/scene_with_camera.h"

namespace objektiv {

namespace {

constexpr int kPreviewDivisors[] = {1, 2, 3, 4, 6, 8, 12};
// A pass of the integrator takes about this long (so that a change is answered soon).
constexpr double kPassSeconds = 0.25;
// The lens's layers are composed again once this many times their last composition's time
// has passed (so that they take at most about a fifth of the time).
constexpr double kLayerSpacing = 4;
constexpr double kLayerDelay = 2;

double Seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

uint8_t Quantise(float v) { return uint8_t(std::clamp(v, 0.f, 1.f) * 255.f + 0.5f); }

std::shared_ptr<const ObjectNode> SensorNode(const SceneDocument& doc) {
  for (const auto& child : doc.root->children)
    if (child->tag == "sensor") return child;
  throw ErrorAt(doc.root->loc, "the scene has no <sensor>");  // (BuildScene says so first)
}

// The to_world a transform property holds (identity where none).
Transform ToWorldOf(const SensorOverrides& s) {
  if (const Property* p = s.Find("to_world"))
    if (const Transform* t = std::get_if<Transform>(&p->data)) return *t;
  return Transform();
}

}  // namespace

const char* ViewLayerName(ViewLayer layer) {
  switch (layer) {
    case ViewLayer::kSum: return "picture";
    case ViewLayer::kPrimary: return "primary";
    case ViewLayer::kGhosts: return "ghosts";
    case ViewLayer::kDiffraction: return "diffraction";
  }
  return "?";
}

ViewSession::ViewSession(const std::string& scene_path, const ViewOptions& options)
    : scene_path_(scene_path), options_(options) {
  Load();
  // Orbit about what the middle of the image shows (else 1 scene unit ahead, or the focus).
  double orbit = 1;
  if (std::optional<Vec3f> p = PointAt(0.5 * full_width_, 0.5 * full_height_))
    orbit = Length(Vec3d(*p) - ToWorldOf(sensor_).Point(Vec3d(0, 0, 0)));
  pose_ = CameraPose::FromToWorld(ToWorldOf(sensor_), orbit);
}

ViewSession::~ViewSession() = default;

// The viewer's film in the scene's document, before it is built: the whole film (its crop
// window left out), at the size asked for (so that the camera is set up once, at that size).
// Returns whether the film had a crop window.
bool WholeFilmOfSize(const SceneDocument& doc, int width, int height) {
  bool cropped = false;
  for (const auto& sensor : doc.root->children)
    if (sensor->tag == "sensor")
      for (const auto& film : sensor->children)
        if (film->tag == "film") {
          cropped = std::erase_if(film->props, [](const Property& p) { return p.name.rfind("crop_", 0) == 0; }) > 0;
          for (const std::pair<const char*, int>& size : {std::pair<const char*, int>{"width", width}, {"height", height}}) {
            if (size.second <= 0) continue;
            const std::string name = size.first;
            std::erase_if(film->props, [&name](const Property& p) { return p.name == name; });
            film->props.push_back(Property{name, int64_t(size.second), "integer", film->loc});
          }
        }
  return cropped;
}

void ViewSession::Load() {
  SceneDocument doc = ParseSceneFile(scene_path_, options_.defines);
  const bool cropped = WholeFilmOfSize(doc, options_.width, options_.height);
  RenderSetup setup = BuildScene(doc, GlassCatalog::Default());
  SensorOverrides sensor = sensor_;
  if (doc_.root == nullptr) sensor = SensorOverrides(SensorNode(doc));
  else sensor.Rebase(SensorNode(doc));
  FilmSettings& film = setup.film;
  if (cropped && doc_.root == nullptr)
    spdlog::warn("{}:{}: the viewer shows the whole film: its crop window is left out (and so is it from the camera "
                 "the viewer saves)", film.loc.file, film.loc.line);
  if (options_.width > 0) film.width = options_.width;
  if (options_.height > 0) film.height = options_.height;
  film.crop = CropWindow{0, 0, film.width, film.height};
  if (dynamic_cast<const StereoCamera*>(setup.camera.get()))
    throw ErrorAt(sensor.scene_sensor().loc, "the viewer shows one camera's image: a '{}' sensor makes a film of "
                  "two, which it does not show (render it with objektiv render)", sensor.type());
  // The camera as the scene has it, unless the viewer changed it or the film's size.
  if (!sensor.set().empty() || setup.camera->width() != film.width || setup.camera->height() != film.height)
    setup.camera = MakeCamera(sensor.Node(), film.width, film.height);
  const bool first = doc_.root == nullptr;
  doc_ = std::move(doc);
  setup_ = std::move(setup);
  scene_exposure_ = setup_.film.exposure;
  if (first) exposure_ = scene_exposure_;
  setup_.film.exposure = float(exposure_);
  sensor_ = std::move(sensor);
  scene_cropped_ = cropped;
  full_width_ = setup_.film.width, full_height_ = setup_.film.height;
  SamplerSettings s = setup_.sampler;
  if (options_.max_spp > 0) s.spp = options_.max_spp;
  setup_.sampler = s;
  sampler_ = MakeSampler(s);
  // Passes over the whole image: an integrator whose iterations span it (sppm) is shown by
  // the path tracer.
  if (dynamic_cast<const WholeImageIntegrator*>(setup_.integrator.get())) {
    spdlog::warn("{}: the viewer shows sppm's image by the path tracer (sppm's iterations cannot be shown one by one); "
                 "objektiv render renders it", scene_path_);
    setup_.integrator = std::make_unique<PathIntegrator>(*setup_.scene, -1, 5);
  }
  // Direct light (one emitter and one BSDF sample) in the preview; the path tracer where the
  // scene has media (direct lighting does not cross their null boundaries: a room lit through
  // fog would be black).
  if (setup_.scene->HasMedia())
    preview_integrator_ = std::make_unique<PathIntegrator>(*setup_.scene, 8, 3);
  else
    preview_integrator_ = std::make_unique<DirectIntegrator>(*setup_.scene, 1, 1);
  preview_cameras_.clear();
  watched_.clear();
  for (const std::string& f : InputFiles()) {
    std::error_code ec;
    watched_[f] = std::filesystem::last_write_time(f, ec);
  }
  Restart();
}

std::unique_ptr<Camera> ViewSession::MakeCamera(const ObjectNode& sensor, int width, int height, bool quiet) const {
  // Quiet after the scene's first load: the lens's set-up is logged once, not at every change.
  const spdlog::level::level_enum level = spdlog::get_level();
  if (doc_.root) spdlog::set_level(std::max(level, quiet ? spdlog::level::err : spdlog::level::warn));
  try {
    std::unique_ptr<Camera> camera = BuildCamera(sensor, width, height, GlassCatalog::Default());
    spdlog::set_level(level);
    return camera;
  } catch (...) {
    spdlog::set_level(level);
    throw;
  }
}

void ViewSession::Restart() {
  restarted_ = std::chrono::steady_clock::now();
  progress_.spp = 0;
  stalled_.clear();
  film_.reset();
  spp_done_ = 0;
  layers_.reset();
  still_preview_shown_ = false;
}

void ViewSession::SetPose(const CameraPose& pose, bool moving) {
  const Transform before = ToWorldOf(sensor_);
  // As the scene reader makes it from the saved matrix (app/view/scene_with_camera.h), so that
  // the saved camera renders the very image.
  const Transform to_world(pose.ToWorld().Matrix());
  pose_ = pose;
  moving_ = moving;
  // A focus point moves with the camera (its distance ahead stays).
  if (const Property* p = sensor_.Find("focus_point"))
    if (const Vec3d* f = std::get_if<Vec3d>(&p->data))
      sensor_.Set("focus_point", to_world.Point(before.Inverse().Point(*f)), "point");
  sensor_.Set("to_world", to_world, "transform");
  // The previews move; the camera of the passes is built again from the node before the next
  // pass (moving it would round its focus differently from a render of the saved camera).
  bool moved = true;
  for (auto& [divisor, camera] : preview_cameras_) moved = moved && camera->MoveTo(to_world);
  if (!moved) preview_cameras_.clear();
  full_camera_stale_ = true;
  Restart();
}

void ViewSession::SetMoving(bool moving) {
  stalled_.clear();
  if (moving_ == moving) return;
  moving_ = moving;
  if (!moving) still_preview_shown_ = false;
}

void ViewSession::SetSensorProperty(const std::string& name, PropertyData value, const std::string& type_name) {
  // The same value again (a slider let go where it was): the image goes on.
  if (const Property* now = sensor_.Find(name); now && now->data.index() == value.index()) {
    const bool same = std::visit(
        [&](const auto& a) {
          using T = std::decay_t<decltype(a)>;
          if constexpr (std::is_same_v<T, double> || std::is_same_v<T, int64_t> || std::is_same_v<T, bool> ||
                        std::is_same_v<T, std::string> || std::is_same_v<T, Vec3d>)
            return a == std::get<T>(value);
          return false;
        },
        now->data);
    if (same) return;
  }
  // A file named from the working directory (a lens file typed in the panel or a script) by
  // its absolute path; else as given (a shipped lens, or a file beside the scene).
  if (const std::string* file = std::get_if<std::string>(&value); file && (name == "lens" || name == "aperture_mask")) {
    std::error_code ec;
    if (std::filesystem::path(*file).is_relative() && std::filesystem::is_regular_file(*file, ec))
      value = std::filesystem::absolute(*file, ec).lexically_normal().string();
  }
  if (name != "lens") {
    if (name == "fnumber" || name == "aperture_diameter") wanted_fnumber_.reset();
    return ChangeSensor([&](SensorOverrides& s) { s.Set(name, value, type_name); });
  }
  // Another lens: the f-number asked for (before a slower lens took it wide open) if this one
  // opens so far, else wide open (said).
  if (wanted_fnumber_) {
    try {
      const double n = *wanted_fnumber_;
      ChangeSensor([&](SensorOverrides& s) { s.Set(name, value, type_name), s.SetFloat("fnumber", n); });
      wanted_fnumber_.reset();
      return;
    } catch (const InputError&) {
    }
  }
  try {
    ChangeSensor([&](SensorOverrides& s) { s.Set(name, value, type_name); });
  } catch (const InputError&) {
    if (!(sensor_.Find("fnumber") || sensor_.Find("aperture_diameter"))) throw;
    if (!wanted_fnumber_) wanted_fnumber_ = sensor_.Float("fnumber");
    ChangeSensor([&](SensorOverrides& s) {
      s.Set(name, value, type_name);
      s.Unset("fnumber"), s.Unset("aperture_diameter");
    });
    notice_ = fmt::format("{} does not open as far as the f-number asked: wide open", std::get<std::string>(value));
    spdlog::warn("{}", notice_);
  }
}

std::string ViewSession::TakeNotice() {
  std::string n;
  n.swap(notice_);
  return n;
}

void ViewSession::ChangeSensor(const std::function<void(SensorOverrides&)>& change) {
  SensorOverrides changed = sensor_;
  change(changed);
  std::unique_ptr<Camera> camera = MakeCamera(changed.Node(), full_width_, full_height_);  // throws: nothing changes
  sensor_ = std::move(changed);
  setup_.camera = std::move(camera);
  full_camera_stale_ = false;
  preview_cameras_.clear();
  Restart();
}

std::optional<Vec3f> ViewSession::PointAt(double x, double y) {
  BuildCameraWhereItStands();  // (moved since the last pass)
  // Through the middle of the lens, else (a mirror lens's obstruction) points around it.
  const Vec2f lens_points[] = {{0.5f, 0.5f}, {0.5f, 0.8f}, {0.8f, 0.5f}, {0.5f, 0.2f}, {0.2f, 0.5f}, {0.5f, 0.95f}};
  for (Vec2f u : lens_points) {
    CameraSample s;
    s.p_film = Vec2f(float(x), float(y));
    s.p_lens = u;
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    std::optional<CameraRay> ray = setup_.camera->GenerateRay(s, lambda);
    if (!ray) continue;
    std::optional<SurfaceInteraction> hit = setup_.scene->Intersect(ray->ray);
    return hit ? std::optional<Vec3f>(hit->p) : std::nullopt;
  }
  return std::nullopt;
}

bool ViewSession::FocusAt(double x, double y) {
  const std::string& type = sensor_.type();
  if (type != "realistic" && type != "thinlens") return false;
  std::optional<Vec3f> p = PointAt(x, y);
  if (!p) return false;
  if (type == "realistic") {
    SetSensorProperty("focus_point", Vec3d(*p), "point");
    return true;
  }
  // The thin lens's plane in focus lies at camera-space depth focus_distance.
  const double depth = ToWorldOf(sensor_).Inverse().Point(Vec3d(*p)).z;
  if (!(depth > 0)) return false;
  SetSensorProperty("focus_distance", depth, "float");
  return true;
}

void ViewSession::SetExposure(double stops) {
  exposure_ = stops;
  setup_.film.exposure = float(stops);
  if (!shown_xyz_.empty()) ShowXyz(shown_xyz_, display_.width, display_.height);
}

void ViewSession::SetLayer(ViewLayer layer) {
  layer_ = layer;
  // What is shown, in the new layer: the last preview frame (its parts kept), or the passes.
  if (progress_.preview && !preview_.picture.empty()) {
    ShowPreview();
  } else if (film_ && !moving_) {
    ShowFilm();
  }
}

bool ViewSession::HasLensLayers() const {
  const auto* real = dynamic_cast<const RealisticCamera*>(setup_.camera.get());
  return real && real->effects().Any();
}

int ViewSession::PreviewDivisor() const {
  if (!(preview_seconds_per_pixel_ > 0)) return 4;
  // The frame's time less the lamps' ghosts', but at least a third of it for the picture.
  const double frame = 1 / std::max(options_.preview_fps, 1e-3);
  const double target = std::max(frame - preview_flare_seconds_, frame / 3);
  for (int d : kPreviewDivisors) {
    const double pixels = double(std::max(1, full_width_ / d)) * std::max(1, full_height_ / d);
    if (pixels * preview_seconds_per_pixel_ <= target) return d;
  }
  return kPreviewDivisors[std::size(kPreviewDivisors) - 1];
}

const Camera& ViewSession::PreviewCamera(int divisor) {
  auto it = preview_cameras_.find(divisor);
  if (it == preview_cameras_.end()) {
    // Each camera ray with its hero wavelength alone: spectral MIS traces every ray back
    // through the lens at the sample's other wavelengths (about 3x the lens's work, most of a
    // preview frame through a dispersive lens) for less colour noise than one sample shows.
    SensorOverrides preview = sensor_;
    if (preview.type() == "realistic") preview.SetBoolean("spectral_mis", false);
    const int w = std::max(1, full_width_ / divisor), h = std::max(1, full_height_ / divisor);
    it = preview_cameras_.emplace(divisor, MakeCamera(preview.Node(), w, h, /*quiet=*/true)).first;
  }
  return *it->second;
}

void ViewSession::PreviewFrame(int divisor, const std::atomic<bool>* stop) {
  const Camera& camera = PreviewCamera(divisor);
  const int w = camera.width(), h = camera.height();
  Film film(w, h, CropWindow{0, 0, w, h}, setup_.film.filter);
  Sampler sampler(SamplerKind::kIndependent, 1, setup_.sampler.seed);
  RenderOptions ro;
  ro.spp_begin = 0, ro.spp_end = 1;
  ro.threads = options_.threads;
  // A moving preview's frame is short (its resolution is cut for that) and finishes: stopped
  // at each of a drag's steps, its frames would show black where they stopped. The still one,
  // at full resolution, stops for a change.
  ro.stop = moving_ ? nullptr : stop;
  const auto start = std::chrono::steady_clock::now();
  const RenderStats stats = Render(camera, *preview_integrator_, sampler, film, ro);
  if (stats.seconds > 0) preview_seconds_per_pixel_ = stats.seconds / (double(w) * h);
  preview_.width = w, preview_.height = h;
  preview_.picture = film.Xyz();
  const auto flare_start = std::chrono::steady_clock::now();
  PreviewFlare(camera, ro.stop);
  preview_flare_seconds_ = Seconds(flare_start);
  const double seconds = Seconds(start);
  ShowPreview();
  progress_.preview = true;
  progress_.spp = 0;
  progress_.width = w, progress_.height = h;
  progress_.frame_seconds = seconds;
  progress_.camera_pass_rate = stats.CameraPassRate();
  progress_.layers = false;
}

void ViewSession::PreviewFlare(const Camera& camera, const std::atomic<bool>* stop) {
  // As the passes' lens layers show them (render/lens_layers.h): where the lens has effects,
  // the point lights' own images (camera rays never meet a point light) and, with ghosts on,
  // their ghosts; at preview quality, without glare and diffraction.
  preview_.lights.clear(), preview_.ghosts.clear();
  const auto* real = dynamic_cast<const RealisticCamera*>(&camera);
  if (!real || !real->effects().Any()) return;
  FlareSettings flare = FlareSettings::Preview();
  flare.ghosts = real->effects().ghosts;
  flare.light_images = true;
  flare.stop = stop;
  FlareImages f = RenderFlare(*setup_.scene, *real, CropWindow{0, 0, camera.width(), camera.height()}, flare);
  preview_.lights = std::move(f.lights), preview_.ghosts = std::move(f.ghosts);
}

void ViewSession::ShowPreview() {
  // The layer shown, as the passes' layers hold the parts: the lamps' images in the primary
  // image, the ghosts alone in theirs; the preview has no diffraction (black).
  std::vector<float> xyz = preview_.picture;
  if (layer_ == ViewLayer::kGhosts || layer_ == ViewLayer::kDiffraction) std::fill(xyz.begin(), xyz.end(), 0.f);
  auto add = [&xyz](const std::vector<float>& layer) {
    for (size_t i = 0; i < layer.size() && i < xyz.size(); ++i) xyz[i] += layer[i];
  };
  if (layer_ == ViewLayer::kSum || layer_ == ViewLayer::kPrimary) add(preview_.lights);
  if (layer_ == ViewLayer::kSum || layer_ == ViewLayer::kGhosts) add(preview_.ghosts);
  ShowXyz(xyz, preview_.width, preview_.height);
}

void ViewSession::BuildCameraWhereItStands() {
  if (!full_camera_stale_) return;
  setup_.camera = MakeCamera(sensor_.Node(), full_width_, full_height_);
  full_camera_stale_ = false;
}

void ViewSession::Pass(const std::atomic<bool>* stop) {
  BuildCameraWhereItStands();
  if (!film_) film_ = std::make_unique<Film>(MakeRenderFilm(setup_, 16, options_.threads));
  const int max_spp = setup_.sampler.spp;
  const int end = stop_at_ > 0 ? std::min(stop_at_, max_spp) : max_spp;
  int n = 1;
  if (spp_done_ > 0 && pass_seconds_per_spp_ > 0) n = int(std::clamp(kPassSeconds / pass_seconds_per_spp_, 1.0, 64.0));
  n = std::min(n, end - spp_done_);
  RenderOptions ro;
  ro.spp_begin = spp_done_, ro.spp_end = spp_done_ + n;
  ro.threads = options_.threads;
  ro.stop = stop;
  const RenderStats stats = Render(*setup_.camera, *setup_.integrator, *sampler_, *film_, ro);
  if (!stats.Partial()) {
    spp_done_ += n;
    pass_seconds_per_spp_ = stats.seconds / n;
  }
  // The lens's layers take seconds (the ghosts' bundles; a change stops them between chunks
  // of bundles): not while the controls are in use (the first after the passes have run
  // kLayerDelay seconds, or at their end), then spaced so that they take a fifth of the time.
  const bool first = !layers_ && (Seconds(restarted_) >= kLayerDelay || spp_done_ == end);
  const bool again = layers_ && Seconds(layers_time_) >= kLayerSpacing * layers_seconds_;
  if (HasLensLayers() && !stats.Partial() && (first || again)) {
    const auto start = std::chrono::steady_clock::now();
    LensLayers layers = ComposeLensLayers(*setup_.scene, *setup_.camera, *film_, setup_.sampler.seed, stop);
    if (!layers.stopped) {  // (stopped for a change: the image starts again anyway)
      layers_ = std::move(layers);
      layers_film_ = film_->Xyz();
      layers_seconds_ = Seconds(start);
      layers_time_ = std::chrono::steady_clock::now();
    }
  }
  ShowFilm();
  progress_.preview = false;
  progress_.spp = spp_done_;
  progress_.width = full_width_, progress_.height = full_height_;
  progress_.frame_seconds = stats.seconds;
  progress_.camera_pass_rate = stats.CameraPassRate();
  progress_.layers = layers_.has_value();
}

bool ViewSession::Step(const std::atomic<bool>* stop) {
  progress_.max_spp = setup_.sampler.spp;
  // A camera that cannot be built again (a lens file broken on disk since): nothing to do
  // until the next change or reload, rather than the same error twice a second.
  if (!stalled_.empty()) return false;
  try {
    return Frame(stop);
  } catch (const InputError& e) {
    stalled_ = e.what();
    throw;
  }
}

bool ViewSession::Frame(const std::atomic<bool>* stop) {
  if (moving_) {
    PreviewFrame(PreviewDivisor(), stop);
    return true;
  }
  if (!still_preview_shown_ && spp_done_ == 0) {
    PreviewFrame(1, stop);
    still_preview_shown_ = true;
    return true;
  }
  if (spp_done_ >= (stop_at_ > 0 ? std::min(stop_at_, setup_.sampler.spp) : setup_.sampler.spp)) return false;
  Pass(stop);
  return true;
}

void ViewSession::ShowFilm() {
  if (!layers_) return ShowXyz(film_->Xyz(), full_width_, full_height_);
  // The picture and the primary layer with the film as it is now: the layers' film part
  // replaced by the film's later passes (the ghosts and the diffraction as last composed).
  auto with_film_now = [&](std::vector<float> xyz) {
    const std::vector<float> now = film_->Xyz();
    for (size_t i = 0; i < xyz.size() && i < now.size() && i < layers_film_.size(); ++i) xyz[i] += now[i] - layers_film_[i];
    return xyz;
  };
  switch (layer_) {
    case ViewLayer::kSum: return ShowXyz(with_film_now(layers_->Sum()), layers_->width, layers_->height);
    case ViewLayer::kPrimary: return ShowXyz(with_film_now(layers_->primary), layers_->width, layers_->height);
    case ViewLayer::kGhosts:
      if (!layers_->ghosts.empty()) return ShowXyz(layers_->ghosts, layers_->width, layers_->height);
      break;
    case ViewLayer::kDiffraction:
      if (!layers_->diffraction.empty()) return ShowXyz(layers_->diffraction, layers_->width, layers_->height);
      break;
  }
  ShowXyz(std::vector<float>(size_t(3) * layers_->width * layers_->height, 0.f), layers_->width, layers_->height);
}

void ViewSession::ShowXyz(const std::vector<float>& xyz, int width, int height) {
  if (&xyz != &shown_xyz_) shown_xyz_ = xyz;  // (for another exposure of the same picture)
  const Image display =
      ApplyToneMap(XyzToImage(xyz, width, height, *setup_.film.color_space, float(exposure_)), setup_.film.tonemap);
  display_.width = width, display_.height = height;
  display_.frame++;
  display_.rgba.resize(size_t(4) * width * height);
  for (size_t i = 0; i < size_t(width) * height; ++i) {
    for (int c = 0; c < 3; ++c) display_.rgba[4 * i + c] = Quantise(display.pixels[3 * i + c]);
    display_.rgba[4 * i + 3] = 255;
  }
}

// The output checks' refusals (CLI::ValidationError, a command-line error elsewhere) as the
// viewer's InputError.
void CheckOutputs(const std::vector<Output>& outputs) {
  try {
    CheckOutputsWritable(outputs);
    CheckOutputsAreNotInputs(outputs);
  } catch (const CLI::ValidationError& e) {
    throw InputError(e.what());
  }
}

void ViewSession::SaveImage(const std::string& exr_path) const {
  if (std::filesystem::path(exr_path).extension() != ".exr")
    throw InputError(fmt::format("{}: the image is saved as an .exr (the PNG is written beside it)", exr_path));
  if (!film_ || spp_done_ == 0)
    throw InputError(fmt::format("{}: no pass of the integrator has finished yet: nothing to save", exr_path));
  std::filesystem::path png = std::filesystem::path(exr_path).replace_extension(".png");
  CheckOutputs({{"the image", exr_path}, {"the PNG beside it", png.string()}});
  std::vector<ImageAttribute> header = {{"objektiv:spp", spp_done_}, {"objektiv:scene", scene_path_},
                                        {"objektiv:saved_by", std::string("objektiv view")}};
  WriteRenderImages(setup_, *film_, options_.threads, exr_path, png.string(), header);
}

void ViewSession::SaveScene(const std::string& xml_path) const {
  CheckOutputs({{"the scene with the viewer's camera", xml_path}});
  SceneWithCamera what;
  what.scene_path = scene_path_;
  what.sensor = &sensor_;
  what.defines = options_.defines;
  if (options_.width > 0 || options_.height > 0) what.film_size = Vec2i(full_width_, full_height_);
  if (exposure_ != scene_exposure_) what.exposure = exposure_;
  what.whole_film = scene_cropped_;
  if (options_.max_spp > 0) what.sample_count = options_.max_spp;
  WriteSceneWithCamera(what, xml_path);
}

std::optional<std::string> ViewSession::ReloadIfChanged() {
  // Files read since (a lens file chosen in the panel) are watched from now on.
  for (const std::string& f : InputFiles())
    if (!watched_.count(f)) {
      std::error_code ec;
      watched_[f] = std::filesystem::last_write_time(f, ec);
    }
  bool changed = false;
  for (const auto& [file, time] : watched_) {
    std::error_code ec;
    if (std::filesystem::last_write_time(file, ec) != time) changed = true;
  }
  if (!changed) return std::nullopt;
  try {
    Load();
    spdlog::info("{}: read again", scene_path_);
    return std::string();
  } catch (const InputError& e) {
    // Keep the last good scene; try again when a file changes again.
    for (auto& [file, time] : watched_) {
      std::error_code ec;
      time = std::filesystem::last_write_time(file, ec);
    }
    return std::string(e.what());
  }
}

}  // namespace objektiv
