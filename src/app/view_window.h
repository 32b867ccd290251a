// The viewer's window (GLFW, OpenGL 3.3, Dear ImGui): the image as it converges on the left,
// drawn pixel for pixel where it fits (else scaled down to fit), the panel of controls on the
// right (app/view_panel.h), the mouse and the keys moving the camera:
//   left drag: orbit about the centre; right drag: look around (turn in place);
//   middle drag or shift + left drag: move sideways and up; wheel: dolly toward the centre;
//   W A S D (Q E down, up): fly, faster with shift; a left click without a drag: focus on
//   what lies under the cursor; ctrl + click: orbit about it; ctrl + S: save the image and the
//   camera (to the panel's file names); ctrl + Q or Escape: close.
// With a script (app/view/view_script.h) the window runs it instead of taking input, a step a
// frame, the session on the window's thread, and closes when it ends.
#pragma once
#include <memory>
#include <optional>

#include "app/view/view_script.h"
#include "app/view/view_session.h"

namespace objektiv {

// Returns the exit status: 0 when closed (or the script ended), 1 when the window cannot be
// opened (no display) or the script failed (the message on stderr).
int RunViewWindow(std::unique_ptr<ViewSession> session, std::optional<ViewScript> script);

}  // namespace objektiv
