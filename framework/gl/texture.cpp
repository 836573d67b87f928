#include "gl/texture.h"

#include "gl/handle.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <utility>

namespace rtlab::gl {

bool TextureDesc::operator==(const TextureDesc& o) const {
  return target == o.target && format == o.format && width == o.width && height == o.height && depth == o.depth &&
         layers == o.layers && levels == o.levels && minFilter == o.minFilter && magFilter == o.magFilter && wrap == o.wrap &&
         depthCompare == o.depthCompare && std::memcmp(border, o.border, sizeof(border)) == 0;
}

std::size_t bytesPerTexel(GLenum format) {
  switch (format) {
  case GL_R8: case GL_R8UI: return 1;
  case GL_RG8: case GL_R16F: case GL_R16UI: case GL_R16: case GL_DEPTH_COMPONENT16: return 2;
  case GL_RGB16F: return 6;
  case GL_RGBA8: case GL_SRGB8_ALPHA8: case GL_RG16F: case GL_R32F: case GL_DEPTH_COMPONENT24:
  case GL_DEPTH_COMPONENT32F: case GL_DEPTH24_STENCIL8: case GL_R11F_G11F_B10F: case GL_RGB10_A2: return 4;
  case GL_RGBA16F: case GL_RG32F: case GL_RG32UI: case GL_RGBA16: case GL_RGBA16UI: return 8;
  case GL_RGB32F: return 12;
  case GL_RGBA32F: case GL_RGBA32UI: return 16;
  default: return 4;
  }
}

bool isDepthFormat(GLenum format) {
  return format == GL_DEPTH_COMPONENT16 || format == GL_DEPTH_COMPONENT24 || format == GL_DEPTH_COMPONENT32F ||
         format == GL_DEPTH24_STENCIL8;
}

namespace {
int mipSize(int size, int level) { return std::max(size >> level, 1); }
} // namespace

int TextureDesc::widthAt(int level) const { return mipSize(width, level); }
int TextureDesc::heightAt(int level) const { return mipSize(height, level); }

int TextureDesc::layersAt(int level) const {
  switch (target) {
  case GL_TEXTURE_2D_ARRAY: return layers;
  case GL_TEXTURE_CUBE_MAP: return 6;
  case GL_TEXTURE_3D: return mipSize(depth, level);
  default: return 1;
  }
}

std::size_t TextureDesc::bytes() const {
  std::size_t total = 0;
  for (int l = 0; l < levels; ++l)
    total += std::size_t(widthAt(l)) * std::size_t(heightAt(l)) * std::size_t(layersAt(l)) * bytesPerTexel(format);
  return total;
}

const char* targetName(GLenum target) {
  switch (target) {
  case GL_TEXTURE_2D: return "2D";
  case GL_TEXTURE_2D_ARRAY: return "2D array";
  case GL_TEXTURE_3D: return "3D";
  case GL_TEXTURE_CUBE_MAP: return "cube";
  default: return "unknown target";
  }
}

std::string descDifference(const TextureDesc& a, const TextureDesc& b) {
  auto hex = [](unsigned v) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%04X", v);
    return std::string(text);
  };
  auto field = [](const char* name, const std::string& x, const std::string& y) { return std::string(name) + " " + x + " vs " + y; };
  if (a.target != b.target) return field("target", targetName(a.target), targetName(b.target));
  if (a.format != b.format) return field("format", hex(a.format), hex(b.format));
  if (a.width != b.width || a.height != b.height)
    return field("size", std::to_string(a.width) + "x" + std::to_string(a.height),
                 std::to_string(b.width) + "x" + std::to_string(b.height));
  if (a.depth != b.depth) return field("depth", std::to_string(a.depth), std::to_string(b.depth));
  if (a.layers != b.layers) return field("layers", std::to_string(a.layers), std::to_string(b.layers));
  if (a.levels != b.levels) return field("levels", std::to_string(a.levels), std::to_string(b.levels));
  if (a.minFilter != b.minFilter) return field("min filter", hex(a.minFilter), hex(b.minFilter));
  if (a.magFilter != b.magFilter) return field("mag filter", hex(a.magFilter), hex(b.magFilter));
  if (a.wrap != b.wrap) return field("wrap", hex(a.wrap), hex(b.wrap));
  if (a.depthCompare != b.depthCompare) return field("depth compare", a.depthCompare ? "on" : "off", b.depthCompare ? "on" : "off");
  if (!(a == b)) return "border color";
  return "";
}

Texture::Texture(const TextureDesc& desc, const std::string& label) : m_desc(desc) {
  glCreateTextures(desc.target, 1, &m_name);
  if (desc.target == GL_TEXTURE_2D_ARRAY)
    glTextureStorage3D(m_name, desc.levels, desc.format, desc.width, desc.height, desc.layers);
  else if (desc.target == GL_TEXTURE_3D)
    glTextureStorage3D(m_name, desc.levels, desc.format, desc.width, desc.height, desc.depth);
  else
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
