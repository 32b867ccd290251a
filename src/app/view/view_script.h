// A scripted run of the viewer: the controls as a user would use them, one command a line, so
// that a run can be repeated (tests, screenshots for the README) with a window or without.
//
//   set NAME VALUE          a property of the sensor (app/view/sensor_overrides.h: as declared)
//   reset NAME              back to the scene's value
//   focus X Y               focus on what lies under film pixel (X, Y) (continuous coordinates)
//   orbit YAW PITCH         degrees, about the orbit centre
//   turn YAW PITCH          degrees, in place
//   move RIGHT UP FORWARD   scene units, along the camera's axes
//   dolly FACTOR            the distance to the orbit centre times FACTOR
//   look-at X Y             turn to what lies under film pixel (X, Y), and orbit about it
//   exposure STOPS
//   layer NAME              picture, primary, ghosts or diffraction
//   preview [moving]        one preview frame (at reduced resolution with `moving`)
//   samples N               render until the passes have N samples per pixel
//   save FILE.exr           the image (and the PNG beside it), as render writes them
//   save-camera FILE.xml    the scene with this camera (beside the scene)
//   screenshot FILE.png     the window as shown; without a window, the image shown
//   quit
// A change is shown at once (a preview frame). Text after # is a comment. Relative file names
// are relative to the working directory, as on the command line (save-camera's must lie beside
// the scene); names hold no spaces.
#pragma once
#include <string>
#include <vector>

#include "app/view/view_session.h"

namespace objektiv {

struct ScriptCommand {
  int line = 0;
  std::string verb;
  std::vector<std::string> args;
};

// InputError "file:line: ..." for an unknown command or a wrong number of arguments.
std::vector<ScriptCommand> ReadViewScript(const std::string& path);

class ViewScript {
 public:
  ViewScript(std::string path, std::vector<ScriptCommand> commands) : path_(std::move(path)), commands_(std::move(commands)) {}

  // What the window does after a step.
  struct Action {
    enum Kind { kDraw, kScreenshot, kDone } kind = kDraw;
    std::string path;  // kScreenshot's
  };
  // One step: a command, or one frame of `samples`. InputError "file:line: ..." where a
  // command fails (a value the camera refuses, a file that cannot be written).
  Action Step(ViewSession& session);
  bool done() const { return next_ >= commands_.size(); }

 private:
  std::string path_;
  std::vector<ScriptCommand> commands_;
  size_t next_ = 0;
};

}  // namespace objektiv
