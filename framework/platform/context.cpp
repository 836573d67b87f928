#include "platform/context.h"

#include <glad/gl.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <functional>
#include <utility>
#include <vector>

#include "gl/debug.h"
#include "platform/egl_context.h"
#include "platform/glfw_context.h"
#include "platform/osmesa_context.h"
#include "util/error.h"
#include "util/log.h"

namespace rtlab {
namespace {

std::string glString(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}

std::string lowercase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool isSoftwareRenderer(const std::string& renderer) {
  const std::string r = lowercase(renderer);
  for (const char* name : {"llvmpipe", "softpipe", "swrast"})
    if (r.find(name) != std::string::npos) return true;
  return false;
}

// Mesa's libEGL prints "libEGL warning: ..." lines while probing a platform that is not there; the
// failure reason ends up in our one-line error anyway. Quiet it unless the user asked for EGL's
// own log or for rtlab's debug log.
void quietEglProbing() {
  if (std::getenv("EGL_LOG_LEVEL") || logLevel() == LogLevel::Debug) return;
  setenv("EGL_LOG_LEVEL", "fatal", 0);
}

struct Attempt {
  const char* name;
  std::function<std::unique_ptr<Context>()> create;
};

// Tries each attempt in order; the first that works wins. Otherwise one line naming all of them.
std::unique_ptr<Context> firstThatWorks(const std::vector<Attempt>& attempts) {
  std::string reasons;
  for (const Attempt& attempt : attempts) {
    try {
      std::unique_ptr<Context> context = attempt.create();
      logInfo("GL context: " + context->backendName() + ", " + context->info().renderer + ", " +
              context->info().version);
      return context;
    } catch (const Error& e) {
      std::string why = e.what();
      // loadGl's messages start with the backend name; it is already the label here.
      const std::string prefix = std::string(attempt.name) + " ";
      if (why.rfind(prefix, 0) == 0) why.erase(0, prefix.size());
      logDebug(std::string(attempt.name) + " failed: " + why);
      reasons += (reasons.empty() ? "" : "; ") + std::string(attempt.name) + ": " + why;
    }
  }
  throw Error(ExitCode::NoContext, "no OpenGL 4.5 context: " + reasons);
}

} // namespace

void Context::loadGl(ProcLoader getProcAddress, const std::string& backend) {
  const int version = gladLoadGL(getProcAddress);
  if (version == 0)
    throw Error(ExitCode::NoContext, backend + " could not load the OpenGL entry points");
  const int major = GLAD_VERSION_MAJOR(version);
  const int minor = GLAD_VERSION_MINOR(version);
  if (major * 10 + minor < 45)
    throw Error(ExitCode::NoContext, backend + " provides OpenGL " + std::to_string(major) + "." +
                                         std::to_string(minor) + ", rtlab needs 4.5 core");
  m_info.vendor = glString(GL_VENDOR);
  m_info.renderer = glString(GL_RENDERER);
  m_info.version = glString(GL_VERSION);
  m_info.glsl = glString(GL_SHADING_LANGUAGE_VERSION);
  m_info.software = isSoftwareRenderer(m_info.renderer);
  GLint flags = 0;
  glGetIntegerv(GL_CONTEXT_FLAGS, &flags);
  logDebug(backend + ((flags & GL_CONTEXT_FLAG_DEBUG_BIT) != 0 ? ": debug context"
                                                               : ": no debug context (debug output enabled on a plain one)"));
  installDebugOutput();
}

Backend parseBackend(const std::string& name) {
  if (name == "auto") return Backend::Auto;
  if (name == "egl") return Backend::Egl;
  if (name == "osmesa") return Backend::OsMesa;
  usageError("unknown backend '" + name + "' (choices: auto, egl, osmesa)");
}

std::unique_ptr<Context> createHeadlessContext(Backend backend) {
  std::vector<Attempt> attempts;
  if (backend == Backend::Auto || backend == Backend::Egl) {
    quietEglProbing();
    attempts.push_back({"egl-surfaceless", [] { return createEglContext(EglPlatform::Surfaceless); }});
    attempts.push_back({"egl-device", [] { return createEglContext(EglPlatform::Device); }});
  }
  if (backend == Backend::Auto || backend == Backend::OsMesa)
    attempts.push_back({"osmesa", [] { return createOsMesaContext(); }});
  return firstThatWorks(attempts);
}

std::unique_ptr<Context> createWindowContext(int width, int height, const std::string& title) {
  std::unique_ptr<Context> context = createGlfwContext(width, height, title);
  logInfo("GL context: " + context->backendName() + ", " + context->info().renderer + ", " +
          context->info().version);
  return context;
}

} // namespace rtlab
