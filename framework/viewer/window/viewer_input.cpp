#include "viewer/window/viewer_input.h"

#include "ui/panels.h"
#include "viewer/viewer_actions.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace rtlab {
namespace {

bool keyPressed(int key) {
  return ImGui::IsKeyPressed(key, false);
}

void stepBookmark(ViewerState& state, int delta) {
  if (state.bookmarks.empty()) {
    setStatus(state, "no bookmarks (rtlab view --bookmarks FILE)", false);
    return;
  }
  const int n = int(state.bookmarks.size());
  const int next = state.bookmark < 0 ? (delta > 0 ? 0 : n - 1) : std::clamp(state.bookmark + delta, 0, n - 1);
  runGuarded(state, [&] { bookmarkAction(state, next); });
}

} // namespace

InputResult handleViewerInput(GLFWwindow* window, ViewerState& state, float dt) {
  InputResult result;
  const ImGuiIO& io = ImGui::GetIO();
  if (!io.WantCaptureKeyboard) {
    if (keyPressed(GLFW_KEY_ESCAPE)) result.quit = true;
    if (keyPressed(GLFW_KEY_F12)) state.pendingScreenshots.push_back(state.screenshotPathInput);
    if (keyPressed(GLFW_KEY_TAB)) panelAction(state, !state.showPanel);
    if (keyPressed(GLFW_KEY_L)) state.lecture = !state.lecture;
    if (keyPressed(GLFW_KEY_RIGHT)) stepBookmark(state, +1);
    if (keyPressed(GLFW_KEY_LEFT)) stepBookmark(state, -1);
    if (keyPressed(GLFW_KEY_R)) resetCameraAction(state);
    if (keyPressed(GLFW_KEY_F)) frameSceneAction(state);
  }
  // The frame's region in window coordinates (the layout is in framebuffer pixels).
  const float scale = std::max(io.DisplayFramebufferScale.x, 1e-3f);
  const PixelRect& frame = state.layout.frame;
  const float frameX = float(frame.x) / scale, frameW = std::max(float(frame.width) / scale, 1.0f);
  const bool ctrl = io.KeyCtrl;
  if (!io.WantCaptureMouse && ctrl && io.MouseDown[0] && state.compare.mode != CompareMode::Off) {
    state.compare.divider = std::clamp((io.MousePos.x - frameX) / frameW, 0.0f, 1.0f);
    return result;
  }
  CameraInput in;
  in.dt = dt;
  in.viewport = {std::max(int(frameW), 1), std::max(int(float(frame.height) / scale), 1)};
  if (!io.WantCaptureMouse) {
    in.mouseDelta = {io.MouseDelta.x, io.MouseDelta.y};
    in.orbit = io.MouseDown[0];
    in.pan = io.MouseDown[1] || io.MouseDown[2];
    in.wheel = io.MouseWheel;
  }
  if (!io.WantCaptureKeyboard && !ctrl) {
    auto axis = [&](int plus, int minus) {
      return float(glfwGetKey(window, plus) == GLFW_PRESS) - float(glfwGetKey(window, minus) == GLFW_PRESS);
    };
    in.fly = {axis(GLFW_KEY_D, GLFW_KEY_A), axis(GLFW_KEY_E, GLFW_KEY_Q), axis(GLFW_KEY_W, GLFW_KEY_S)};
    in.fast = io.KeyShift;
  }
  if (!std::isfinite(in.mouseDelta.x) || !std::isfinite(in.mouseDelta.y)) in.mouseDelta = glm::vec2(0);
  if (state.camera.update(in)) syncCameraToParams(state);
  return result;
}

} // namespace rtlab
