// Keyboard and mouse of the viewer: the camera (orbit, pan, zoom, WASD fly; R reset, F frame),
// Esc quit, F12 screenshot, Tab panel on/off, L lecture mode, Left/Right bookmarks, Ctrl+drag
// the compare divider. Input ImGui wants (a slider being dragged, a text field) is left to it.
#pragma once
#include "viewer/viewer_state.h"

struct GLFWwindow;

namespace rtlab {

struct InputResult {
  bool quit = false;
};

// Call between ImGui::NewFrame() and rendering; `dt` in seconds.
InputResult handleViewerInput(GLFWwindow* window, ViewerState& state, float dt);

} // namespace rtlab
