// One GL context interface, three implementations chosen at run time (docs/architecture.md
// "Contexts and the GL loader"): EGL (surfaceless platform, then device platform), OSMesa, and a
// GLFW window. Creating a context
// makes it current, loads the GL 4.5 core entry points through glad with that context's
// getProcAddress (rtlab never links libGL/libOpenGL), checks the version, and installs KHR_debug.
#pragma once
#include <memory>
#include <string>

struct GLFWwindow;

namespace rtlab {

enum class Backend { Auto, Egl, OsMesa };

// What the active context reports (glGetString), filled after loading.
struct GlInfo {
  std::string vendor, renderer, version, glsl;
  bool software = false; // Mesa llvmpipe / softpipe / swrast: timer queries do not measure rasterization
};

class Context {
public:
  virtual ~Context() = default;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  // "egl-surfaceless", "egl-device", "osmesa" or "glfw".
  virtual std::string backendName() const = 0;
  virtual void makeCurrent() = 0;
  const GlInfo& info() const { return m_info; }

  // Window contexts only; headless ones return false / do nothing.
  virtual bool isWindow() const { return false; }
  virtual GLFWwindow* window() const { return nullptr; }
  virtual bool shouldClose() const { return false; }
  virtual void pollEvents() {}
  virtual void swapBuffers() {}
  // Drawable size in pixels (window framebuffer); {0,0} for headless contexts.
  virtual void framebufferSize(int& width, int& height) const { width = height = 0; }

protected:
  Context() = default;
  // Loads GL through glad with `getProcAddress`, fills m_info, installs debug output. Throws
  // Error(NoContext) if GL 4.5 core is not available.
  using ProcLoader = void (*(*)(const char*))();
  void loadGl(ProcLoader getProcAddress, const std::string& backend);
  GlInfo m_info;
};

Backend parseBackend(const std::string& name); // auto|egl|osmesa, else Error(Usage)

// Headless: Auto tries EGL surfaceless, EGL device, then OSMesa. Throws Error(NoContext) with one
// line naming every backend tried and why each failed.
std::unique_ptr<Context> createHeadlessContext(Backend backend);

// A window of the given size; throws Error(NoContext) when there is no display or no GL 4.5.
std::unique_ptr<Context> createWindowContext(int width, int height, const std::string& title);

} // namespace rtlab
