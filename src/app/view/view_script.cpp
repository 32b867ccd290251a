#include "app/view/view_script.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "base/error.h"
#include "base/text_file.h"

namespace objektiv {

namespace {

// Verb -> (fewest, most) arguments.
const std::map<std::string, std::pair<size_t, size_t>>& Verbs() {
  static const std::map<std::string, std::pair<size_t, size_t>> kVerbs = {
      {"set", {2, 2}},   {"reset", {1, 1}},    {"focus", {2, 2}},       {"orbit", {2, 2}},
      {"turn", {2, 2}},  {"move", {3, 3}},     {"dolly", {1, 1}},       {"look-at", {2, 2}},
      {"exposure", {1, 1}}, {"layer", {1, 1}}, {"preview", {0, 1}},     {"samples", {1, 1}},
      {"save", {1, 1}},  {"save-camera", {1, 1}}, {"screenshot", {1, 1}}, {"quit", {0, 0}}};
  return kVerbs;
}

double Number(const ScriptCommand& c, size_t i, const std::string&) {
  const std::string& t = c.args[i];
  double v = 0;
  auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || ptr != t.data() + t.size() || !std::isfinite(v))
    throw InputError(fmt::format("'{}' is not a number", t));
  return v;
}

// A film position (continuous pixel coordinates) on the film.
void CheckPixel(const ViewSession& session, double x, double y) {
  const int w = session.setup().film.width, h = session.setup().film.height;
  if (x < 0 || y < 0 || x >= w || y >= h)
    throw InputError(fmt::format("({:g}, {:g}) is outside the {}x{} film", x, y, w, h));
}

}  // namespace

std::vector<ScriptCommand> ReadViewScript(const std::string& path) {
  std::istringstream in(ReadTextFile(path, "view script"));
  std::vector<ScriptCommand> commands;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    text = text.substr(0, text.find('#'));  // a comment, whole line or after the command
    std::istringstream words(text);
    ScriptCommand c;
    c.line = line;
    if (!(words >> c.verb)) continue;
    // `set NAME VALUE`: the value is the rest of the line (a point's "x, y, z").
    std::string w;
    if (c.verb == "set") {
      if (words >> w) c.args.push_back(w);
      std::string rest;
      std::getline(words, rest);
      rest.erase(0, rest.find_first_not_of(" \t"));
      rest.erase(rest.find_last_not_of(" \t\r") + 1);
      if (!rest.empty()) c.args.push_back(rest);
    } else {
      while (words >> w) c.args.push_back(w);
    }
    auto v = Verbs().find(c.verb);
    if (v == Verbs().end()) throw MakeInputError(path, line, "unknown command '{}'", c.verb);
    if (c.args.size() < v->second.first || c.args.size() > v->second.second)
      throw MakeInputError(path, line, "{} takes {} argument{}", c.verb,
                           v->second.first == v->second.second ? fmt::format("{}", v->second.first)
                                                               : fmt::format("{} to {}", v->second.first, v->second.second),
                           v->second.second == 1 ? "" : "s");
    commands.push_back(std::move(c));
  }
  return commands;
}

ViewScript::Action ViewScript::Step(ViewSession& session) {
  if (done()) return {Action::kDone, ""};
  const ScriptCommand& c = commands_[next_];
  const std::string& v = c.verb;
  auto at = [&](const std::exception& e) { return MakeInputError(path_, c.line, "{}: {}", v, e.what()); };
  try {
    if (v == "samples") {
      const double count = Number(c, 0, path_);
      if (count != std::floor(count)) throw InputError(fmt::format("'{}' is not a whole number", c.args[0]));
      const int n = int(std::clamp(count, -1.0, 1e9));
      if (n < 1 || n > session.setup().sampler.spp)
        throw InputError(fmt::format("{} is not between 1 and the scene's {} samples per pixel (view --spp sets it)",
                                     c.args[0], session.setup().sampler.spp));
      // A frame at a time, so that a window shows them.
      session.StopPassesAt(n);
      if (session.progress().spp < n && session.Step()) return {Action::kDraw, ""};
      session.StopPassesAt(0);
      ++next_;
      return {Action::kDraw, ""};
    }
    ++next_;
    CameraPose pose = session.pose();
    // A change is shown at once (a preview frame), so that a screenshot after it shows it.
    const bool change = v == "set" || v == "reset" || v == "focus" || v == "orbit" || v == "turn" || v == "move" ||
                        v == "dolly" || v == "look-at";
    if (v == "set") {
      SensorValue value = ParseSensorValue(session.sensor().type(), c.args[0], c.args[1]);
      session.SetSensorProperty(c.args[0], value.data, value.type_name);
    } else if (v == "reset") {
      if (!SensorPropertyDecl(session.sensor().type(), c.args[0]))
        throw InputError(fmt::format("a '{}' sensor has no property '{}'", session.sensor().type(), c.args[0]));
      session.ResetSensorProperty(c.args[0]);
    } else if (v == "focus") {
      CheckPixel(session, Number(c, 0, path_), Number(c, 1, path_));
      if (!session.FocusAt(Number(c, 0, path_), Number(c, 1, path_)))
        throw InputError("nothing to focus on there (no surface under the pixel, or a camera without focus)");
    } else if (v == "orbit" || v == "turn") {
      if (v == "orbit") pose.Orbit(Number(c, 0, path_), Number(c, 1, path_));
      else pose.Turn(Number(c, 0, path_), Number(c, 1, path_));
      session.SetPose(pose, false);
    } else if (v == "move") {
      pose.Move(Number(c, 0, path_), Number(c, 1, path_), Number(c, 2, path_));
      session.SetPose(pose, false);
    } else if (v == "dolly") {
      const double f = Number(c, 0, path_);
      if (!(f > 0)) throw InputError("the factor must be positive");
      pose.Dolly(f);
      session.SetPose(pose, false);
    } else if (v == "look-at") {
      CheckPixel(session, Number(c, 0, path_), Number(c, 1, path_));
      std::optional<Vec3f> p = session.PointAt(Number(c, 0, path_), Number(c, 1, path_));
      if (!p) throw InputError("no surface under that pixel");
      pose.LookAt(Vec3d(*p));
      session.SetPose(pose, false);
    } else if (v == "exposure") {
      // As the film's exposure property is bounded (io/load_film.cpp).
      const double stops = Number(c, 0, path_);
      if (std::abs(stops) > 64) throw InputError(fmt::format("{} is not between -64 and 64 stops", c.args[0]));
      session.SetExposure(stops);
    } else if (v == "layer") {
      const std::string& name = c.args[0];
      bool found = false;
      for (ViewLayer l : {ViewLayer::kSum, ViewLayer::kPrimary, ViewLayer::kGhosts, ViewLayer::kDiffraction})
        if (name == ViewLayerName(l)) session.SetLayer(l), found = true;
      if (!found) throw InputError(fmt::format("'{}' is not picture, primary, ghosts or diffraction", name));
      if (!session.HasLensLayers() && name != "picture")
        throw InputError("the sensor makes no lens layers (its ghosts and diffraction are off)");
    } else if (v == "preview") {
      if (!c.args.empty() && c.args[0] != "moving") throw InputError(fmt::format("'{}' is not 'moving'", c.args[0]));
      const bool moving = !c.args.empty();
      session.SetPose(session.pose(), moving);
      session.Step();
      session.SetMoving(false);
    } else if (v == "save") {
      session.SaveImage(c.args[0]);
    } else if (v == "save-camera") {
      session.SaveScene(c.args[0]);
    } else if (v == "screenshot") {
      if (session.display().width == 0) session.Step();  // nothing shown yet: the first frame
      return {Action::kScreenshot, c.args[0]};
    } else if (v == "quit") {
      next_ = commands_.size();
      return {Action::kDone, ""};
    }
    if (change) session.Step();
  } catch (const InputError& e) {
    throw at(e);
  }
  return {Action::kDraw, ""};
}

}  // namespace objektiv
