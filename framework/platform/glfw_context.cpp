#include "platform/glfw_context.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>

#include "platform/dri_driver.h"
#include "util/error.h"
#include "util/log.h"

namespace rtlab {
namespace {

std::string g_lastGlfwError; // the text of GLFW's last error, for our messages

void onGlfwError(int code, const char* description) {
  g_lastGlfwError = description ? description : "error " + std::to_string(code);
  logDebug("GLFW: " + g_lastGlfwError);
}

std::string lastError() { return g_lastGlfwError.empty() ? "unknown GLFW error" : g_lastGlfwError; }

bool envSet(const char* name) {
  const char* v = std::getenv(name);
  return v && *v;
}

class GlfwContext final : public Context {
public:
  ~GlfwContext() override {
    if (m_window) glfwDestroyWindow(m_window);
    glfwTerminate();
  }

  std::string backendName() const override { return "glfw"; }
  void makeCurrent() override { glfwMakeContextCurrent(m_window); }

  bool isWindow() const override { return true; }
  GLFWwindow* window() const override { return m_window; }
  bool shouldClose() const override { return glfwWindowShouldClose(m_window) != 0; }
  void pollEvents() override { glfwPollEvents(); }
  void swapBuffers() override { glfwSwapBuffers(m_window); }
  void framebufferSize(int& width, int& height) const override {
    glfwGetFramebufferSize(m_window, &width, &height);
  }

  // glfwInit has succeeded before this is called; the destructor terminates GLFW.
  void init(int width, int height, const std::string& title) {
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    // A debug context (docs/architecture.md "GL errors"); installDebugOutput enables the output.
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
    m_window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!m_window)
      throw Error(ExitCode::NoContext,
                  "could not open a window with OpenGL 4.5 core: " + lastError());
    glfwMakeContextCurrent(m_window);
    keepDriDriversResident();
    glfwSwapInterval(1);
    loadGl(&glfwGetProcAddress, "glfw");
  }

private:
  GLFWwindow* m_window = nullptr;
};

} // namespace

std::unique_ptr<Context> createGlfwContext(int width, int height, const std::string& title) {
  glfwSetErrorCallback(onGlfwError);
  g_lastGlfwError.clear();
  const std::string noDisplay = "no display for a window (run under 'xvfb-run -a', or render headless with "
                                "'rtlab render'); DISPLAY/WAYLAND_DISPLAY unset or unusable: ";
  if (!envSet("DISPLAY") && !envSet("WAYLAND_DISPLAY"))
    throw Error(ExitCode::NoContext, noDisplay + "neither is set");
  if (!glfwInit()) throw Error(ExitCode::NoContext, noDisplay + lastError());
  auto context = std::make_unique<GlfwContext>();
  context->init(width, height, title);
  return context;
}

} // namespace rtlab
