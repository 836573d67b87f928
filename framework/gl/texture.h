// An owned, immutable-storage texture (glTextureStorage*), with the description it was made from
// so that pools can reuse it and stats can count its bytes.
#pragma once
#include "gl/gl.h"

#include <cstddef>
#include <string>

namespace rtlab::gl {

struct TextureDesc {
  GLenum target = GL_TEXTURE_2D;   // GL_TEXTURE_2D or GL_TEXTURE_CUBE_MAP
  GLenum format = GL_RGBA8;        // sized internal format
  int width = 0, height = 0;
  int levels = 1;
  GLenum minFilter = GL_NEAREST, magFilter = GL_NEAREST;
  GLenum wrap = GL_CLAMP_TO_EDGE;
  bool depthCompare = false;       // GL_COMPARE_REF_TO_TEXTURE with GL_LEQUAL (shadow samplers)
  float border[4] = {1, 1, 1, 1};  // used with GL_CLAMP_TO_BORDER

  bool operator==(const TextureDesc& o) const;
  std::size_t bytes() const;       // estimate from the format's bits per texel, all faces and levels
};

std::size_t bytesPerTexel(GLenum format);
bool isDepthFormat(GLenum format);

class Texture {
public:
  Texture() = default;
  Texture(const TextureDesc& desc, const std::string& label);
  ~Texture() { reset(); }
  Texture(Texture&& o) noexcept;
  Texture& operator=(Texture&& o) noexcept;
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;

  GLuint id() const { return m_name; }
  const TextureDesc& desc() const { return m_desc; }
  explicit operator bool() const { return m_name != 0; }
  void bind(GLuint unit) const { glBindTextureUnit(unit, m_name); }
  void reset();

private:
  GLuint m_name = 0;
  TextureDesc m_desc;
};

} // namespace rtlab::gl
