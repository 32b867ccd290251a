// `objektiv view SCENE.xml`: the scene through its camera in a window, converging as it
// renders, the camera and the lens under the mouse and the panel (app/view_window.h); or a
// scripted run without a window (--headless), or the preview's speed (--benchmark).
#include <chrono>
#include <cstdio>
#include <map>

#include <fmt/format.h>

#include "app/cli_values.h"
#include "app/commands.h"
#include "app/view_window.h"
#include "base/error.h"
#include "base/log.h"
#include "io/image_io.h"
#include "app/view/view_script.h"

namespace objektiv {
namespace {

struct ViewArgs {
  std::string scene, script, size;
  std::vector<std::string> defines;
  int spp = 0, threads = 0, benchmark = 0;
  double fps = 30;
  bool headless = false, quiet = false;
};

// The picture shown, as a PNG (a scripted run without a window).
void WriteDisplay(const DisplayImage& d, const std::string& path) {
  Image image(d.width, d.height, {"R", "G", "B"});
  for (size_t i = 0; i < size_t(d.width) * d.height; ++i)
    for (int c = 0; c < 3; ++c) image.pixels[3 * i + c] = d.rgba[4 * i + c] / 255.f;
  WritePng(path, image);
}

int RunScriptHeadless(ViewSession& session, ViewScript& script) {
  for (;;) {
    const ViewScript::Action a = script.Step(session);
    if (a.kind == ViewScript::Action::kScreenshot) WriteDisplay(session.display(), a.path);
    if (a.kind == ViewScript::Action::kDone) return 0;
  }
}

// The preview's speed while the camera moves: `frames` frames, each orbiting the camera by a
// degree, at the resolution the preview picks for its target; then the first frame at rest and
// the first passes of the integrator.
int RunBenchmark(ViewSession& session, int frames, double target_fps) {
  using Clock = std::chrono::steady_clock;
  auto seconds = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  CameraPose pose = session.pose();
  // Warm up: the preview's first frame measures the time per pixel.
  session.SetPose(pose, true);
  session.Step();
  std::map<std::pair<int, int>, int> sizes;
  const Clock::time_point start = Clock::now();
  for (int i = 0; i < frames; ++i) {
    pose.Orbit(1, 0);
    session.SetPose(pose, true);
    session.Step();
    sizes[{session.progress().width, session.progress().height}]++;
  }
  const double moving = seconds(start);
  std::string rendered;
  for (const auto& [size, n] : sizes) rendered += fmt::format("{}{}x{} ({} frames)", rendered.empty() ? "" : ", ", size.first, size.second, n);
  std::printf("view benchmark: %s, %dx%d film\n", session.scene_path().c_str(), session.setup().film.width,
              session.setup().film.height);
  std::printf("moving preview: %d frames in %.3f s = %.1f frames/s (target %.0f), rendered at %s\n", frames, moving,
              frames / moving, target_fps, rendered.c_str());
  session.SetMoving(false);
  Clock::time_point t = Clock::now();
  session.Step();
  std::printf("still preview at full resolution: %.1f ms\n", seconds(t) * 1e3);
  for (int pass = 0; pass < 3 && session.progress().spp < session.progress().max_spp; ++pass) {
    t = Clock::now();
    session.Step();
    const ViewProgress& p = session.progress();
    std::printf("pass %d: %d spp in all, %.1f ms\n", pass + 1, p.spp, seconds(t) * 1e3);
  }
  return 0;
}

int RunView(const ViewArgs& a) {
  SetupLogging(a.quiet ? 0 : 1);
  ViewOptions options;
  for (const std::string& d : a.defines) {
    const size_t eq = d.find('=');
    if (eq == std::string::npos || eq == 0) throw CLI::ValidationError("-D", "expects name=value, got '" + d + "'");
    if (!options.defines.emplace(d.substr(0, eq), d.substr(eq + 1)).second)
      throw CLI::ValidationError("-D", d.substr(0, eq) + " is given twice");
  }
  if (!a.size.empty()) {
    const std::optional<std::vector<int>> v = ParseCounts(a.size, 'x', 2);
    if (!v || (*v)[0] < 1 || (*v)[1] < 1 || (*v)[0] > 16384 || (*v)[1] > 16384)
      throw CLI::ValidationError("--size", "expects WIDTHxHEIGHT, each 1 to 16384 pixels, got '" + a.size + "'");
    options.width = (*v)[0], options.height = (*v)[1];
  }
  options.max_spp = a.spp;
  options.threads = a.threads;
  options.preview_fps = a.fps;
  if (a.benchmark > 0 && !a.script.empty())
    throw CLI::ValidationError("--benchmark", "runs without a script: give --benchmark or --script");
  if (a.headless && a.script.empty() && a.benchmark == 0)
    throw CLI::ValidationError("--headless", "needs --script or --benchmark: without a window, a script says what to do");
  std::optional<ViewScript> script;
  if (!a.script.empty()) script.emplace(a.script, ReadViewScript(a.script));
  auto session = std::make_unique<ViewSession>(a.scene, options);
  if (a.benchmark > 0) return RunBenchmark(*session, a.benchmark, a.fps);
  if (a.headless) return RunScriptHeadless(*session, *script);
  return RunViewWindow(std::move(session), std::move(script));
}

}  // namespace

std::function<int()> AddViewCommand(CLI::App& app) {
  auto args = std::make_shared<ViewArgs>();
  CLI::App* cmd = app.add_subcommand("view", "Look through the lens live: the scene in a window, converging as it renders");
  cmd->add_option("scene", args->scene, "Scene file (XML)")->required()->check(CLI::ExistingFile);
  cmd->add_option("-D,--define", args->defines, "Set a scene <default> parameter: -D name=value");
  cmd->add_option("--size", args->size, "The film's size instead of the scene's: WIDTHxHEIGHT");
  cmd->add_option("--spp", args->spp, "Samples per pixel to stop at (default: the scene's sample count)")
      ->check(CLI::Range(1, 1 << 20));
  cmd->add_option("-t,--threads", args->threads, "Render threads (default: all cores)")->check(CLI::Range(1, 4096));
  cmd->add_option("--fps", args->fps, "Frames per second the moving preview aims for (default 30)")
      ->check(CLI::Range(1.0, 1000.0));
  cmd->add_option("--script", args->script, "Run these viewer commands (docs: README, the viewer) instead of taking input")
      ->check(CLI::ExistingFile);
  cmd->add_flag("--headless", args->headless, "No window: run --script (screenshots are the image shown) or --benchmark");
  cmd->add_option("--benchmark", args->benchmark,
                  "No window: move the camera for N preview frames and print the frames per second, then the first passes")
      ->check(CLI::Range(1, 1000000));
  cmd->add_flag("-q,--quiet", args->quiet, "Only warnings and errors");
  return [args] { return RunView(*args); };
}

}  // namespace objektiv
