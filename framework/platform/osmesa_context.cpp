#include "platform/osmesa_context.h"

// osmesa.h includes <GL/gl.h> for its types; glad is not included in this file, and no gl* symbol
// is called here (they would bind to libOSMesa's exports, bypassing the loader).
#include <GL/osmesa.h>

#include <vector>

#include "util/error.h"

namespace rtlab {
namespace {

// The default framebuffer is never drawn to (rtlab renders into its own FBOs); it only has to exist.
constexpr int kBufferSize = 16;

[[noreturn]] void osmesaFail(const std::string& what) { throw Error(ExitCode::NoContext, what); }

void (*osmesaProc(const char* name))() {
  return reinterpret_cast<void (*)()>(OSMesaGetProcAddress(name));
}

class OsMesaContext final : public Context {
public:
  OsMesaContext() : m_buffer(static_cast<size_t>(kBufferSize * kBufferSize * 4)) {}
  ~OsMesaContext() override {
    if (m_context) OSMesaDestroyContext(m_context);
  }

  std::string backendName() const override { return "osmesa"; }

  void makeCurrent() override {
    if (!OSMesaMakeCurrent(m_context, m_buffer.data(), GL_UNSIGNED_BYTE, kBufferSize, kBufferSize))
      osmesaFail("OSMesaMakeCurrent failed");
  }

  // OSMesa has no debug-context attribute: installDebugOutput (Context::loadGl) enables
  // GL_DEBUG_OUTPUT and its callback on this plain context, which counts errors all the same
  // (docs/architecture.md "GL errors"; the render test GlErrors.DebugOutputReportsAnError checks it).
  void init() {
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA,
                           OSMESA_DEPTH_BITS, 0,
                           OSMESA_STENCIL_BITS, 0,
                           OSMESA_ACCUM_BITS, 0,
                           OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 4,
                           OSMESA_CONTEXT_MINOR_VERSION, 5,
                           0};
    m_context = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!m_context) osmesaFail("OSMesaCreateContextAttribs(OpenGL 4.5 core) failed");
    makeCurrent();
    loadGl(&osmesaProc, "osmesa");
  }

private:
  OSMesaContext m_context = nullptr;
  std::vector<unsigned char> m_buffer;
};

} // namespace

std::unique_ptr<Context> createOsMesaContext() {
  auto context = std::make_unique<OsMesaContext>();
  context->init();
  return context;
}

} // namespace rtlab
