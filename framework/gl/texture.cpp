#include "gl/texture.h"

#include "gl/handle.h"

#include <cstring>
#include <utility>

namespace rtlab::gl {

bool TextureDesc::operator==(const TextureDesc& o) const {
  return target == o.target && format == o.format && width == o.width && height == o.height &&
         levels == o.levels && minFilter == o.minFilter && magFilter == o.magFilter && wrap == o.wrap &&
         depthCompare == o.depthCompare && std::memcmp(border, o.border, sizeof(border)) == 0;
}

std::size_t bytesPerTexel(GLenum format) {
  switch (format) {
  case GL_R8: return 1;
  case GL_RG8: case GL_R16F: case GL_DEPTH_COMPONENT16: return 2;
  case GL_RGBA8: case GL_SRGB8_ALPHA8: case GL_RG16F: case GL_R32F: case GL_DEPTH_COMPONENT24:
  case GL_DEPTH_COMPONENT32F: case GL_DEPTH24_STENCIL8: case GL_R11F_G11F_B10F: case GL_RGB10_A2: return 4;
  case GL_RGBA16F: case GL_RG32F: case GL_RG32UI: case GL_RGBA16: return 8;
  case GL_RGB32F: return 12;
  case GL_RGBA32F: case GL_RGBA32UI: return 16;
  default: return 4;
  }
}

bool isDepthFormat(GLenum format) {
  return format == GL_DEPTH_COMPONENT16 || format == GL_DEPTH_COMPONENT24 || format == GL_DEPTH_COMPONENT32F ||
         format == GL_DEPTH24_STENCIL8;
}

std::size_t TextureDesc::bytes() const {
  std::size_t total = 0;
  int w = width, h = height;
  for (int l = 0; l < levels; ++l) {
    total += std::size_t(w) * std::size_t(h) * bytesPerTexel(format);
    w = w > 1 ? w / 2 : 1;
    h = h > 1 ? h / 2 : 1;
  }
  return total * (target == GL_TEXTURE_CUBE_MAP ? 6 : 1);
}

Texture::Texture(const TextureDesc& desc, const std::string& label) : m_desc(desc) {
  glCreateTextures(desc.target, 1, &m_name);
  glTextureStorage2D(m_name, desc.levels, desc.format, desc.width, desc.height);
  glTextureParameteri(m_name, GL_TEXTURE_MIN_FILTER, GLint(desc.minFilter));
  glTextureParameteri(m_name, GL_TEXTURE_MAG_FILTER, GLint(desc.magFilter));
  glTextureParameteri(m_name, GL_TEXTURE_WRAP_S, GLint(desc.wrap));
  glTextureParameteri(m_name, GL_TEXTURE_WRAP_T, GLint(desc.wrap));
  glTextureParameteri(m_name, GL_TEXTURE_WRAP_R, GLint(desc.wrap));
  glTextureParameteri(m_name, GL_TEXTURE_MAX_LEVEL, desc.levels - 1);
  if (desc.wrap == GL_CLAMP_TO_BORDER) glTextureParameterfv(m_name, GL_TEXTURE_BORDER_COLOR, desc.border);
  if (desc.depthCompare) {
    glTextureParameteri(m_name, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(m_name, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  }
  if (!label.empty()) setObjectLabel(GL_TEXTURE, m_name, label);
}

Texture::Texture(Texture&& o) noexcept : m_name(std::exchange(o.m_name, 0)), m_desc(o.m_desc) {}

Texture& Texture::operator=(Texture&& o) noexcept {
  if (this != &o) {
    reset();
    m_name = std::exchange(o.m_name, 0);
    m_desc = o.m_desc;
  }
  return *this;
}

void Texture::reset() {
  if (m_name) glDeleteTextures(1, &m_name);
  m_name = 0;
}

} // namespace rtlab::gl
