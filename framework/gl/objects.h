// The GL object kinds rtlab uses, each an owned Handle (handle.h).
#pragma once
#include "gl/handle.h"

namespace rtlab::gl {

struct BufferTraits {
  static constexpr GLenum kIdentifier = GL_BUFFER;
  static GLuint create() { GLuint n = 0; glCreateBuffers(1, &n); return n; }
  static void destroy(GLuint n) { glDeleteBuffers(1, &n); }
};
struct VertexArrayTraits {
  static constexpr GLenum kIdentifier = GL_VERTEX_ARRAY;
  static GLuint create() { GLuint n = 0; glCreateVertexArrays(1, &n); return n; }
  static void destroy(GLuint n) { glDeleteVertexArrays(1, &n); }
};
struct FramebufferTraits {
  static constexpr GLenum kIdentifier = GL_FRAMEBUFFER;
  static GLuint create() { GLuint n = 0; glCreateFramebuffers(1, &n); return n; }
  static void destroy(GLuint n) { glDeleteFramebuffers(1, &n); }
};
struct SamplerTraits {
  static constexpr GLenum kIdentifier = GL_SAMPLER;
  static GLuint create() { GLuint n = 0; glCreateSamplers(1, &n); return n; }
  static void destroy(GLuint n) { glDeleteSamplers(1, &n); }
};
struct ProgramTraits {
  static constexpr GLenum kIdentifier = GL_PROGRAM;
  static GLuint create() { return glCreateProgram(); }
  static void destroy(GLuint n) { glDeleteProgram(n); }
};
template <GLenum kStage>
struct ShaderTraits {
  static constexpr GLenum kIdentifier = GL_SHADER;
  static GLuint create() { return glCreateShader(kStage); }
  static void destroy(GLuint n) { glDeleteShader(n); }
};

using Buffer = Handle<BufferTraits>;
using VertexArray = Handle<VertexArrayTraits>;
using Framebuffer = Handle<FramebufferTraits>;
using Sampler = Handle<SamplerTraits>;
using ProgramHandle = Handle<ProgramTraits>;

// Queries are created per target, so they get a small class of their own.
class Query {
public:
  Query() = default;
  Query(GLenum target, const std::string& label);
  ~Query() { reset(); }
  Query(Query&& o) noexcept;
  Query& operator=(Query&& o) noexcept;
  Query(const Query&) = delete;
  Query& operator=(const Query&) = delete;
  GLuint id() const { return m_name; }
  void reset();

private:
  GLuint m_name = 0;
};

} // namespace rtlab::gl
