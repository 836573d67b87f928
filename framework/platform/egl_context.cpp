#include "platform/egl_context.h"

#define EGL_NO_X11
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>
#include <vector>

#include "platform/dri_driver.h"
#include "util/error.h"
#include "util/log.h"

namespace rtlab {
namespace {

std::string eglErrorName(EGLint error) {
  switch (error) {
  case EGL_SUCCESS: return "EGL_SUCCESS";
  case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
  case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
  case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
  case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
  case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
  case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
  case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
  case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
  case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
  case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
  case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
  case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
  case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
  case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
  default: {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%04X", static_cast<unsigned>(error));
    return buf;
  }
  }
}

[[noreturn]] void fail(const std::string& what) { throw Error(ExitCode::NoContext, what); }
[[noreturn]] void failEgl(const std::string& call) {
  fail(call + " failed (" + eglErrorName(eglGetError()) + ")");
}

// Whole-word match in a space-separated extension string.
bool hasExtension(const char* extensions, const char* name) {
  if (!extensions) return false;
  const size_t n = std::strlen(name);
  for (const char* p = extensions; (p = std::strstr(p, name)) != nullptr; p += n)
    if ((p == extensions || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

const char* clientExtensions() {
  const char* exts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!exts) fail("no EGL client extensions (is an EGL vendor library installed?)");
  return exts;
}

EGLDisplay platformDisplay(EGLenum platform, void* nativeDisplay) {
  auto getDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!hasExtension(clientExtensions(), "EGL_EXT_platform_base") || !getDisplay)
    fail("no EGL_EXT_platform_base (eglGetPlatformDisplayEXT)");
  EGLDisplay display = getDisplay(platform, nativeDisplay, nullptr);
  if (display == EGL_NO_DISPLAY) failEgl("eglGetPlatformDisplay");
  return display;
}

class EglContext final : public Context {
public:
  explicit EglContext(std::string name) : m_name(std::move(name)) {}
  ~EglContext() override { release(); }

  std::string backendName() const override { return m_name; }

  void makeCurrent() override {
    if (!eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, m_context))
      failEgl("eglMakeCurrent");
  }

  // Initializes `display` (owned from here on), creates the context and makes it current.
  void init(EGLDisplay display) {
    m_display = display;
    EGLint major = 0, minor = 0;
    if (!eglInitialize(m_display, &major, &minor)) {
      m_display = EGL_NO_DISPLAY; // nothing to terminate
      failEgl("eglInitialize");
    }
    keepDriDriversResident();
    const char* exts = eglQueryString(m_display, EGL_EXTENSIONS);
    if (!hasExtension(exts, "EGL_KHR_surfaceless_context")) fail("no EGL_KHR_surfaceless_context");
    if (!eglBindAPI(EGL_OPENGL_API)) failEgl("eglBindAPI(EGL_OPENGL_API)");

    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!hasExtension(exts, "EGL_KHR_no_config_context") &&
        !hasExtension(exts, "EGL_MESA_configless_context")) {
      const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0, EGL_NONE};
      EGLint count = 0;
      if (!eglChooseConfig(m_display, wanted, &config, 1, &count) || count < 1)
        fail("no EGLConfig with EGL_OPENGL_BIT");
    }
    // A debug context (docs/architecture.md "GL errors"): EGL 1.5's EGL_CONTEXT_OPENGL_DEBUG, or
    // EGL_KHR_create_context's debug bit before 1.5.
    const bool egl15 = major > 1 || (major == 1 && minor >= 5);
    const EGLint debugAttrib = egl15 ? EGL_CONTEXT_OPENGL_DEBUG : EGL_CONTEXT_FLAGS_KHR;
    const EGLint debugValue = egl15 ? EGL_TRUE : EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR;
    EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION_KHR, 4, EGL_CONTEXT_MINOR_VERSION_KHR, 5,
                        EGL_CONTEXT_OPENGL_PROFILE_MASK_KHR,
                        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT_KHR, debugAttrib, debugValue, EGL_NONE};
    m_context = eglCreateContext(m_display, config, EGL_NO_CONTEXT, attribs);
    if (m_context == EGL_NO_CONTEXT) {
      // A driver without debug contexts still counts errors: installDebugOutput enables the output.
      logDebug(m_name + ": no debug context (" + eglErrorName(eglGetError()) + "), asking for a plain one");
      attribs[6] = EGL_NONE; // drops the debug pair
      m_context = eglCreateContext(m_display, config, EGL_NO_CONTEXT, attribs);
    }
    if (m_context == EGL_NO_CONTEXT) failEgl("eglCreateContext(OpenGL 4.5 core)");
    if (!eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, m_context))
      failEgl("eglMakeCurrent(surfaceless)");
    logDebug(m_name + ": EGL " + std::to_string(major) + "." + std::to_string(minor) + ", " +
             (eglQueryString(m_display, EGL_VENDOR) ? eglQueryString(m_display, EGL_VENDOR) : "?"));
    loadGl(&eglGetProcAddress, m_name);
  }

private:
  void release() {
    if (m_display == EGL_NO_DISPLAY) return;
    if (m_context != EGL_NO_CONTEXT) {
      if (eglGetCurrentContext() == m_context)
        eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      eglDestroyContext(m_display, m_context);
      m_context = EGL_NO_CONTEXT;
    }
    eglTerminate(m_display);
    eglReleaseThread();
    m_display = EGL_NO_DISPLAY;
  }

  std::string m_name;
  EGLDisplay m_display = EGL_NO_DISPLAY;
  EGLContext m_context = EGL_NO_CONTEXT;
};

std::unique_ptr<Context> createSurfaceless() {
  if (!hasExtension(clientExtensions(), "EGL_MESA_platform_surfaceless"))
    fail("no EGL_MESA_platform_surfaceless");
  auto context = std::make_unique<EglContext>("egl-surfaceless");
  context->init(platformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY));
  return context;
}

std::unique_ptr<Context> createOnDevice() {
  const char* client = clientExtensions();
  if (!hasExtension(client, "EGL_EXT_platform_device")) fail("no EGL_EXT_platform_device");
  auto queryDevices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  if (!queryDevices) fail("no eglQueryDevicesEXT");
  EGLint count = 0;
  if (!queryDevices(0, nullptr, &count)) failEgl("eglQueryDevicesEXT");
  if (count <= 0) fail("no EGL devices");
  std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
  if (!queryDevices(count, devices.data(), &count)) failEgl("eglQueryDevicesEXT");

  // Keep the reasons short: identical failures on several devices are named once.
  std::vector<std::string> reasons;
  for (EGLint i = 0; i < count; ++i) {
    try {
      auto context = std::make_unique<EglContext>("egl-device");
      context->init(platformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[static_cast<size_t>(i)]));
      logDebug("egl-device: using device " + std::to_string(i) + " of " + std::to_string(count));
      return context;
    } catch (const Error& e) {
      std::string why = e.what();
      if (why.rfind("egl-device ", 0) == 0) why.erase(0, 11);
      bool seen = false;
      for (const std::string& r : reasons) seen = seen || r == why;
      if (!seen) reasons.push_back(why);
    }
  }
  std::string all;
  for (size_t i = 0; i < reasons.size(); ++i) all += (i ? ", " : "") + reasons[i];
  fail(all + " (" + std::to_string(count) + (count == 1 ? " device)" : " devices)"));
}

} // namespace

std::unique_ptr<Context> createEglContext(EglPlatform platform) {
  return platform == EglPlatform::Surfaceless ? createSurfaceless() : createOnDevice();
}

} // namespace rtlab
