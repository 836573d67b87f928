#include "viewer/window/viewer_app.h"

#include "frame/registry.h"
#include "gl/debug.h"
#include "platform/context.h"
#include "ui/fonts.h"
#include "ui/panels.h"
#include "util/error.h"
#include "util/log.h"
#include "viewer/viewer_actions.h"
#include "viewer/window/hot_reload.h"
#include "viewer/window/report.h"
#include "viewer/window/screenshot.h"
#include "viewer/window/script_runner.h"
#include "viewer/window/viewer_frame.h"
#include "viewer/window/viewer_input.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <chrono>
#include <memory>

namespace rtlab {
namespace {

// Files dropped onto the window since the last frame; the window's user pointer points at it.
using DroppedFiles = std::vector<std::string>;

void onDrop(GLFWwindow* window, int count, const char** paths) {
  auto* dropped = static_cast<DroppedFiles*>(glfwGetWindowUserPointer(window));
  for (int i = 0; i < count; ++i)
    dropped->emplace_back(paths[i]);
}

// ImGui's context and backends for one window, shut down in reverse order.
class ImGuiSession {
public:
  explicit ImGuiSession(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // no imgui.ini beside the user's files
    ImGui::StyleColorsDark();
    fonts = loadViewerFonts();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 450 core");
  }
  ~ImGuiSession() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;
  ViewerFonts fonts;
};

void initState(ViewerState& state, ViewerOptions& options) {
  ResolvedFrame& f = options.frame;
  state.sceneSpec = f.options.sceneSpec;
  state.scene = f.scene;
  state.params = f.params;
  for (const auto& id : f.techniques)
    state.selection.activate(id);
  state.camera.setHome(state.scene.camera);
  syncCameraFromParams(state); // --set camera.* wins over the scene's camera
  state.camera.setHome(state.camera.camera());
  state.bookmarks = std::move(options.bookmarks);
  state.bookmarksSource = options.bookmarksSource;
}

} // namespace

int runViewer(ViewerOptions options) {
  const ResolvedFrame& f = options.frame;
  const std::string title = "rtlab view — " + f.scene.name + (options.exercise.empty() ? "" : " — " + options.exercise);
  auto context = createWindowContext(f.options.width, f.options.height, title);
  GLFWwindow* window = context->window();
  DroppedFiles dropped;
  glfwSetWindowUserPointer(window, &dropped);
  glfwSetDropCallback(window, onDrop); // before ImGui, which chains the callbacks it replaces
  ImGuiSession imgui(window);
  const TechniqueRegistry& registry = TechniqueRegistry::instance();

  ViewerState state(registry);
  initState(state, options);
  ViewerFrame frame(registry, resolveTiming(f.options.timing, context->info().software));
  ShaderWatcher watcher;
  std::vector<std::string> reloadErrors; // programs whose rebuild failed (the last good one runs)
  std::unique_ptr<ScriptRunner> script;
  if (options.script)
    script = std::make_unique<ScriptRunner>(std::move(*options.script), [&](const std::string& path) {
      writeViewerReport(path, state, frame.renderWidth(), frame.renderHeight());
    });
  auto last = std::chrono::steady_clock::now();
  while (!context->shouldClose() && !state.quit) {
    context->pollEvents();
    const auto now = std::chrono::steady_clock::now();
    const float dt = std::chrono::duration<float>(now - last).count();
    last = now;
    int w = 0, h = 0;
    context->framebufferSize(w, h);
    if (w <= 0 || h <= 0) { // minimized
      glfwWaitEventsTimeout(0.1);
      continue;
    }
    watcher.poll(frame.programs(), reloadErrors);
    for (const auto& path : dropped)
      runGuarded(state, [&] { loadSceneAction(state, path); });
    dropped.clear();

    useLectureFont(imgui.fonts, state.lecture);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (handleViewerInput(window, state, dt).quit) break;
    if (script) script->step(state);

    const float pixelScale = ImGui::GetIO().DisplayFramebufferScale.x;
    state.layout = computeViewerLayout(w, h, state.showPanel, state.panelWidthEm, ImGui::GetFontSize() * pixelScale);
    frame.render(state, w, h, script && script->wantsReference(), f.options.seed);
    state.shaderErrors = reloadErrors;
    if (!frame.shaderError().empty()) state.shaderErrors.push_back(frame.shaderError());
    // A frame that goes to a file shows no transient status ("screenshot a.png" of the last one).
    const bool finalShot = !options.screenshot.empty() && state.frames >= f.options.frames;
    const bool captured = !state.pendingScreenshots.empty() || !state.recordDir.empty() || finalShot;
    drawViewerPanel(state, !captured, w);
    drawFrameOverlays(state, frame.renderWidth(), frame.renderHeight());
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    state.glErrors += drainGlErrors();

    for (const auto& path : state.pendingScreenshots) {
      try {
        writeScreenshot(path, w, h);
        setStatus(state, "screenshot " + path, true);
      } catch (const Error& e) {
        if (script) throw; // a script's output that cannot be written is an error (exit 6)
        setStatus(state, e.what(), false);
      }
    }
    state.pendingScreenshots.clear();
    if (!state.recordDir.empty()) writeScreenshot(recordedFramePath(state.recordDir, state.recordedFrames++), w, h);
    if (script) script->flushReports();
    if (finalShot) {
      writeScreenshot(options.screenshot, w, h);
      break;
    }
    context->swapBuffers();
  }
  return 0;
}

} // namespace rtlab
