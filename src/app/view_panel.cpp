#include "app/view_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>

#include <fmt/format.h>

#include "app/lens_section.h"
#include "base/error.h"
#include "optics/lens_file.h"

namespace objektiv {

namespace {

// Text fields: ImGui edits a fixed buffer.
bool InputText(const char* label, std::string& text) {
  char buffer[1024];
  const size_t n = std::min(text.size(), sizeof(buffer) - 1);
  std::copy_n(text.data(), n, buffer);
  buffer[n] = 0;
  const bool entered = ImGui::InputText(label, buffer, sizeof(buffer), ImGuiInputTextFlags_EnterReturnsTrue);
  text = buffer;
  return entered || ImGui::IsItemDeactivatedAfterEdit();
}

// A change posted to the session's thread (none in a scripted run, whose controls only show).
void Post(ViewWorker* worker, std::function<void(ViewSession&)> change, std::string notice = "") {
  if (worker) worker->Post(std::move(change), std::move(notice));
}

// A sensor property changed by a control.
void PostSet(ViewWorker* worker, const std::string& name, PropertyData value, const std::string& type) {
  Post(worker, [name, value, type](ViewSession& s) { s.SetSensorProperty(name, value, type); });
}

void Choice(ViewWorker* worker, const SensorOverrides& sensor, const char* label, const std::string& name,
            const std::vector<const char*>& choices, const char* fallback) {
  const std::string now = sensor.String(name).value_or(fallback);
  if (ImGui::BeginCombo(label, now.c_str())) {
    for (const char* c : choices)
      if (ImGui::Selectable(c, now == c) && now != c) PostSet(worker, name, std::string(c), "string");
    ImGui::EndCombo();
  }
}

}  // namespace

ViewPanel::ViewPanel(const std::string& scene_path) : lenses_(ShippedLensNames()) {
  namespace fs = std::filesystem;
  const fs::path scene(scene_path);
  const fs::path stem = scene.parent_path() / (scene.stem().string() + "-view");
  image_path_ = stem.string() + ".exr";
  camera_path_ = stem.string() + ".xml";
}

void ViewPanel::Draw(const ViewSnapshot& s, ViewWorker* worker, float x, float y, float width, float height,
                     double fps) {
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(width, height));
  ImGui::Begin("Objektiv", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  const ViewProgress& p = s.progress;
  if (p.preview)
    ImGui::Text("preview %dx%d, direct light, 1 spp", p.width, p.height);
  else
    ImGui::Text("%d of %d spp%s", p.spp, p.max_spp, p.layers ? " + lens layers" : "");
  ImGui::Text("%.1f pictures/s, last %.0f ms", fps, p.frame_seconds * 1e3);
  if (p.camera_pass_rate) ImGui::Text("camera pass rate %.1f%%", *p.camera_pass_rate * 100);
  ImGui::Separator();
  if (!worker) ImGui::BeginDisabled();  // a scripted run: the controls show only
  float exposure = float(s.exposure);
  if (ImGui::SliderFloat("exposure", &exposure, -10, 10, "%.2f stops"))
    Post(worker, [exposure](ViewSession& v) { v.SetExposure(exposure); });
  if (s.has_layers) {
    int layer = int(s.layer);
    const char* names[] = {"picture", "primary", "ghosts", "diffraction"};
    if (ImGui::Combo("layer", &layer, names, 4)) Post(worker, [layer](ViewSession& v) { v.SetLayer(ViewLayer(layer)); });
  }
  if (s.sensor) LensControls(s, worker);
  Files(worker);
  if (!worker) ImGui::EndDisabled();
  if (s.lens_plot && ImGui::CollapsingHeader("lens in cross-section", ImGuiTreeNodeFlags_DefaultOpen))
    DrawLensSection(*s.lens_plot, ImGui::GetContentRegionAvail().x);
  // The last error (until a change or a reload succeeds) or notice, wrapped, below the
  // controls (which it would otherwise push down under the mouse).
  if (!s.error.empty() || !s.notice.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, s.error.empty() ? ImVec4(0.6f, 0.9f, 0.6f, 1) : ImVec4(1, 0.4f, 0.35f, 1));
    ImGui::TextWrapped("%s", s.error.empty() ? s.notice.c_str() : s.error.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::End();
}

void ViewPanel::LensControls(const ViewSnapshot& s, ViewWorker* worker) {
  const SensorOverrides& sensor = *s.sensor;
  const std::string& type = s.sensor_type;
  const bool real = type == "realistic", thin = type == "thinlens";
  ImGui::Text("sensor: %s%s%s", type.c_str(), s.lens_name.empty() ? "" : ", lens ", s.lens_name.c_str());
  if (type == "perspective" || thin) {
    float fov = float(sensor.Float("fov").value_or(0));
    if (fov > 0 && ImGui::SliderFloat("field of view", &fov, 1, 170, "%.1f deg")) PostSet(worker, "fov", double(fov), "float");
  }
  if (!real && !thin) return;
  if (real) {
    if (ImGui::BeginCombo("lens", s.lens_name.c_str())) {
      for (const std::string& name : lenses_)
        if (ImGui::Selectable(name.c_str(), name == sensor.String("lens").value_or("")))
          PostSet(worker, "lens", name, "string");
      ImGui::EndCombo();
    }
    if (InputText("lens file", lens_file_) && !lens_file_.empty()) PostSet(worker, "lens", lens_file_, "string");
  }
  // Focus: metres (from the film for the real lens, along the view for the thin lens), on a
  // logarithmic slider; or a point picked in the image.
  const bool picked = sensor.Find("focus_point") != nullptr;
  float focus = float(sensor.Float("focus_distance").value_or(INFINITY));
  float shown = std::isfinite(focus) ? focus : 1000.f;
  const char* format = picked ? "on the point clicked" : std::isfinite(focus) ? "%.3f m" : "infinity";
  if (ImGui::SliderFloat("focus", &shown, 0.05f, 1000, format, ImGuiSliderFlags_Logarithmic))
    PostSet(worker, "focus_distance", double(shown), "float");
  if (real) {
    ImGui::SameLine();
    if (ImGui::SmallButton("inf"))
      Post(worker, [](ViewSession& v) {
        v.ChangeSensor([](SensorOverrides& o) { o.Unset("focus_distance"), o.Unset("focus_point"); });
      });
  }
  // Aperture.
  const std::optional<double> n = sensor.Float("fnumber");
  float fnumber = float(n.value_or(0));
  if (ImGui::SliderFloat("f-number", &fnumber, real ? 0.7f : 0.5f, 64, n ? "f/%.2f" : "wide open", ImGuiSliderFlags_Logarithmic))
    PostSet(worker, "fnumber", double(fnumber), "float");
  if (real && n) {
    ImGui::SameLine();
    if (ImGui::SmallButton("open"))
      Post(worker, [](ViewSession& v) {
        v.ChangeSensor([](SensorOverrides& o) { o.Unset("fnumber"), o.Unset("aperture_diameter"); });
      });
  }
  int blades = int(sensor.Integer("blades").value_or(0));
  if (ImGui::SliderInt("blades", &blades, 0, 16, blades == 0 ? "round" : "%d") && blades != 1 && blades != 2)
    PostSet(worker, "blades", int64_t(blades), "integer");
  float rotation = float(sensor.Float("blade_rotation").value_or(0));
  if (ImGui::SliderFloat("blade rotation", &rotation, 0, 360, "%.0f deg")) PostSet(worker, "blade_rotation", double(rotation), "float");
  if (!real) return;
  float curvature = float(sensor.Float("blade_curvature").value_or(0));
  if (ImGui::SliderFloat("blade curvature", &curvature, 0, 1, "%.2f")) PostSet(worker, "blade_curvature", double(curvature), "float");
  bool dispersion = sensor.Boolean("dispersion").value_or(true);
  if (ImGui::Checkbox("dispersion", &dispersion)) PostSet(worker, "dispersion", dispersion, "boolean");
  ImGui::SameLine();
  bool transmission = sensor.Boolean("transmission").value_or(true);
  if (ImGui::Checkbox("transmission", &transmission)) PostSet(worker, "transmission", transmission, "boolean");
  Choice(worker, sensor, "vignetting", "vignetting", {"full", "cos4", "aperture", "none"}, "full");
  bool ghosts = sensor.Boolean("ghosts").value_or(false);
  if (ImGui::Checkbox("ghosts and glare", &ghosts)) PostSet(worker, "ghosts", ghosts, "boolean");
  Choice(worker, sensor, "diffraction", "diffraction", {"off", "emitters", "image"}, "off");
  Choice(worker, sensor, "coating", "coating", {"none", "MgF2", "multi"}, "as the lens file");
}

void ViewPanel::SaveBoth(ViewWorker& worker) const {
  // Apart: the camera is saved even before the image has a pass to save.
  const std::string image = image_path_, camera = camera_path_;
  worker.Post([camera](ViewSession& s) { s.SaveScene(camera); }, "saved " + camera);
  worker.Post([image](ViewSession& s) { s.SaveImage(image); }, "saved " + image + " and the camera");
}

void ViewPanel::Files(ViewWorker* worker) {
  ImGui::Separator();
  InputText("image", image_path_);
  ImGui::SameLine();
  if (ImGui::Button("save##image")) {
    const std::string path = image_path_;
    Post(worker, [path](ViewSession& s) { s.SaveImage(path); }, "saved " + path);
  }
  InputText("camera", camera_path_);
  ImGui::SameLine();
  if (ImGui::Button("save##camera")) {
    const std::string path = camera_path_;
    Post(worker, [path](ViewSession& s) { s.SaveScene(path); }, "saved " + path);
  }
}

}  // namespace objektiv
