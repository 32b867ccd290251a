#include "app/view_window.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>

#include "app/view_panel.h"
#include "base/error.h"
#include "io/image_io.h"
#include "app/view/view_worker.h"

namespace objektiv {

namespace {

constexpr int kPanelWidth = 400;
std::string glfw_error;

// The texture the picture is drawn from: nearest-neighbour, so that a pixel-for-pixel picture
// shows exactly the display image's bytes.
class PictureTexture {
 public:
  PictureTexture() {
    glGenTextures(1, &id_);
    glBindTexture(GL_TEXTURE_2D, id_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  ~PictureTexture() { glDeleteTextures(1, &id_); }
  void Upload(const DisplayImage& d) {
    if (d.width <= 0 || d.height <= 0) return;
    glBindTexture(GL_TEXTURE_2D, id_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, d.width, d.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, d.rgba.data());
  }
  ImTextureID id() const { return reinterpret_cast<ImTextureID>(static_cast<intptr_t>(id_)); }

 private:
  GLuint id_ = 0;
};

// The window's framebuffer as an image (rows top to bottom), written as a PNG.
void WriteScreenshot(const std::string& path, int width, int height) {
  std::vector<uint8_t> rgb(size_t(3) * width * height);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  Image image(width, height, {"R", "G", "B"});
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) image.At(x, y, c) = rgb[(size_t(height - 1 - y) * width + x) * 3 + c] / 255.f;
  WritePng(path, image);
}

// Where the picture lies in the window: pixel for pixel at the top left where it fits, else
// scaled down to the room left of the panel.
struct PictureRect {
  float x = 0, y = 0, width = 0, height = 0;
};
PictureRect PlacePicture(int film_width, int film_height, int window_width, int window_height) {
  const float room_w = float(std::max(1, window_width - kPanelWidth)), room_h = float(std::max(1, window_height));
  const float scale = std::min({1.f, room_w / film_width, room_h / film_height});
  return {0, 0, std::floor(film_width * scale), std::floor(film_height * scale)};
}

// Keys that act once per press (seen by a callback: a press and its release between two frames
// still count), and the picture's geometry for the mouse.
struct KeyPresses {
  bool save = false, close = false;
};
void OnKey(GLFWwindow* window, int key, int, int action, int mods) {
  if (action != GLFW_PRESS) return;
  auto* k = static_cast<KeyPresses*>(glfwGetWindowUserPointer(window));
  if (!k || ImGui::GetIO().WantTextInput) return;
  if (key == GLFW_KEY_S && (mods & GLFW_MOD_CONTROL)) k->save = true;
  if (key == GLFW_KEY_ESCAPE || (key == GLFW_KEY_Q && (mods & GLFW_MOD_CONTROL))) k->close = true;
}

// The mouse and the keys moving the camera (interactive runs). The mouse through ImGui's
// state, which keeps a click whose press and release fall between two frames.
class CameraControls {
 public:
  void Update(GLFWwindow* window, const PictureRect& picture, int film_width, int film_height, ViewWorker& worker,
              CameraPose& pose) {
    const ImGuiIO& io = ImGui::GetIO();
    auto in_picture = [&](const ImVec2& m) {
      return m.x >= picture.x && m.y >= picture.y && m.x < picture.x + picture.width && m.y < picture.y + picture.height;
    };
    const bool shift = io.KeyShift, ctrl = io.KeyCtrl;
    bool changed = false;
    // Drags: begun on the picture (not on the panel) with one button.
    if (button_ < 0 && !io.WantCaptureMouse)
      for (int b = 0; b < 3; ++b)
        if (ImGui::IsMouseClicked(b) && in_picture(io.MouseClickedPos[b])) {
          button_ = b, dragged_ = false;
          break;
        }
    if (button_ >= 0) {
      const ImVec2 press = io.MouseClickedPos[button_];
      if (std::hypot(io.MousePos.x - press.x, io.MousePos.y - press.y) > 3) dragged_ = true;
      const double dx = io.MouseDelta.x, dy = io.MouseDelta.y;
      if (dragged_ && io.MouseDown[button_] && (dx != 0 || dy != 0) && std::isfinite(dx) && std::isfinite(dy)) {
        if (button_ == 2 || (button_ == 0 && shift)) {
          const double step = pose.orbit_distance() * 0.002;
          pose.Move(-dx * step, dy * step, 0);
        } else if (button_ == 0) {
          pose.Orbit(-dx * 0.3, dy * 0.3);
        } else {
          pose.Turn(-dx * 0.15, -dy * 0.15);
        }
        changed = true;
      }
      if (ImGui::IsMouseReleased(button_)) {
        if (!dragged_ && button_ == 0) Click(press, picture, film_width, film_height, ctrl, worker);
        button_ = -1;
      }
    }
    // The wheel.
    if (!io.WantCaptureMouse && in_picture(io.MousePos) && io.MouseWheel != 0) {
      pose.Dolly(std::pow(0.9, io.MouseWheel));
      changed = true;
    }
    // Flying (not with ctrl: ctrl + S saves, ctrl + Q closes).
    if (!io.WantCaptureKeyboard && !ctrl) {
      const double dt = std::min(0.1, double(io.DeltaTime));
      const double speed = pose.orbit_distance() * 0.6 * (shift ? 4 : 1) * dt;
      double r = 0, u = 0, f = 0;
      if (glfwGetKey(window, GLFW_KEY_W) == GLFW_PRESS) f += speed;
      if (glfwGetKey(window, GLFW_KEY_S) == GLFW_PRESS) f -= speed;
      if (glfwGetKey(window, GLFW_KEY_D) == GLFW_PRESS) r += speed;
      if (glfwGetKey(window, GLFW_KEY_A) == GLFW_PRESS) r -= speed;
      if (glfwGetKey(window, GLFW_KEY_E) == GLFW_PRESS) u += speed;
      if (glfwGetKey(window, GLFW_KEY_Q) == GLFW_PRESS) u -= speed;
      if (r != 0 || u != 0 || f != 0) {
        pose.Move(r, u, f);
        changed = true;
      }
    }
    if (changed) {
      worker.Post([pose](ViewSession& s) { s.SetPose(pose, true); });
      moving_ = true, still_frames_ = 0;
    } else if (moving_ && button_ < 0 && ++still_frames_ > 2) {  // a few frames without a change: standing still
      worker.Post([](ViewSession& s) { s.SetMoving(false); });
      moving_ = false;
    }
  }
  // Whether the pose should be taken from the session (it moved it itself: ctrl + click).
  bool TakePoseFromSession() {
    const bool take = look_at_pending_;
    look_at_pending_ = false;
    return take;
  }
  bool busy() const { return button_ >= 0 || moving_; }

 private:
  // A click on the picture: focus there, or (ctrl) orbit about the point there.
  void Click(const ImVec2& at, const PictureRect& picture, int film_width, int film_height, bool ctrl,
             ViewWorker& worker) {
    const double fx = (at.x - picture.x) * film_width / picture.width;
    const double fy = (at.y - picture.y) * film_height / picture.height;
    if (ctrl) {
      worker.Post([fx, fy](ViewSession& s) {
        std::optional<Vec3f> p = s.PointAt(fx, fy);
        if (!p) throw InputError("no surface under the cursor to orbit about");
        CameraPose moved = s.pose();
        moved.LookAt(Vec3d(*p));
        s.SetPose(moved, false);
      });
      look_at_pending_ = true;
    } else {
      worker.Post([fx, fy](ViewSession& s) {
        if (!s.FocusAt(fx, fy)) throw InputError("nothing to focus on under the cursor");
      }, "focused on the point clicked");
    }
  }
  int button_ = -1;  // the button of the drag under way (-1: none)
  bool dragged_ = false, moving_ = false, look_at_pending_ = false;
  int still_frames_ = 0;
};

}  // namespace

int RunViewWindow(std::unique_ptr<ViewSession> session, std::optional<ViewScript> script) {
  glfwSetErrorCallback([](int, const char* what) { glfw_error = what; });
  if (!glfwInit()) {
    std::fprintf(stderr, "error: objektiv view cannot open a window (%s): run it on a display (X11, or Xvfb), or "
                 "with --headless\n", glfw_error.c_str());
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  const int film_w = session->setup().film.width, film_h = session->setup().film.height;
  int win_w = film_w + kPanelWidth, win_h = std::max(film_h, 860);
  if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
    int mx, my, mw, mh;
    glfwGetMonitorWorkarea(monitor, &mx, &my, &mw, &mh);
    if (mw > 0 && mh > 0) win_w = std::min(win_w, mw), win_h = std::min(win_h, mh);
  }
  const std::string title = "objektiv view: " + session->scene_path();
  GLFWwindow* window = glfwCreateWindow(win_w, win_h, title.c_str(), nullptr, nullptr);
  if (!window) {
    std::fprintf(stderr, "error: objektiv view cannot open an OpenGL 3.3 window (%s)\n", glfw_error.c_str());
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(script ? 0 : 1);
  KeyPresses keys;
  glfwSetWindowUserPointer(window, &keys);
  glfwSetKeyCallback(window, OnKey);  // (before ImGui's back end, which calls it from its own)
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left behind
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330");

  int status = 0;
  {
    const std::string scene_path = session->scene_path();
    ViewPanel panel(scene_path);
    PictureTexture texture;
    CameraControls controls;
    ViewSnapshot snapshot;
    const Camera* plotted = nullptr;
    std::unique_ptr<ViewWorker> worker;
    ViewSession* scripted = nullptr;
    if (script) {
      scripted = session.get();
    } else {
      worker = std::make_unique<ViewWorker>(std::move(session));
    }
    CameraPose pose;
    bool have_pose = false;
    uint64_t shown = 0;
    std::deque<double> shown_times;  // when the last pictures were shown (for frames per second)
    const auto start = std::chrono::steady_clock::now();
    auto now = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    bool idle = false;  // the last frame showed nothing new and no control was in use
    uint64_t last_generation = 0;  // the snapshot's in the last frame
    while (!glfwWindowShouldClose(window)) {
      // Idle, the window waits for input (or a tenth of a second: a new picture) instead of
      // drawing as fast as it can (with software OpenGL, a core's worth).
      if (idle) glfwWaitEventsTimeout(0.1);
      else glfwPollEvents();
      ViewScript::Action action;
      if (scripted) {
        try {
          action = script->Step(*scripted);
        } catch (const InputError& e) {
          std::fprintf(stderr, "error: %s\n", e.what());
          status = 1;
          break;
        }
        TakeSnapshot(*scripted, snapshot, plotted);
      } else {
        worker->Latest(snapshot);
        if (!have_pose || (!controls.busy() && controls.TakePoseFromSession())) pose = snapshot.pose, have_pose = true;
      }
      if (snapshot.display.frame != shown) {  // a new picture
        texture.Upload(snapshot.display);
        shown = snapshot.display.frame;
        shown_times.push_back(now());
      }
      idle = !scripted && snapshot.generation == last_generation && !controls.busy() &&
             !ImGui::GetIO().WantCaptureMouse && !ImGui::IsAnyItemActive();
      last_generation = snapshot.generation;
      while (shown_times.size() > 1 && now() - shown_times.front() > 2) shown_times.pop_front();
      // Pictures shown in the last two seconds, per second.
      const double fps = shown_times.size() > 1 ? (shown_times.size() - 1) / std::max(1e-6, now() - shown_times.front()) : 0;
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      int fb_w = 0, fb_h = 0;
      glfwGetFramebufferSize(window, &fb_w, &fb_h);
      const PictureRect picture = PlacePicture(film_w, film_h, fb_w, fb_h);
      ImGui::GetBackgroundDrawList()->AddImage(texture.id(), ImVec2(picture.x, picture.y),
                                               ImVec2(picture.x + picture.width, picture.y + picture.height));
      panel.Draw(snapshot, worker.get(), float(fb_w - kPanelWidth), 0, float(kPanelWidth), float(fb_h), fps);
      if (worker) {
        controls.Update(window, picture, film_w, film_h, *worker, pose);
        if (keys.save) panel.SaveBoth(*worker);
        // (Escape in an open list or menu closes that, not the window.)
        if (keys.close && !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel))
          glfwSetWindowShouldClose(window, GLFW_TRUE);
        keys = KeyPresses();
      }
      ImGui::Render();
      glViewport(0, 0, fb_w, fb_h);
      glClearColor(0.09f, 0.09f, 0.1f, 1);
      glClear(GL_COLOR_BUFFER_BIT);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      if (action.kind == ViewScript::Action::kScreenshot) {
        try {
          WriteScreenshot(action.path, fb_w, fb_h);
        } catch (const InputError& e) {
          std::fprintf(stderr, "error: %s\n", e.what());
          status = 1;
          break;
        }
      }
      glfwSwapBuffers(window);
      if (action.kind == ViewScript::Action::kDone) break;
    }
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}

}  // namespace objektiv
