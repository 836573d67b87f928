// An owned, immutable-storage texture (glTextureStorage*), with the description it was made from
// so that pools can reuse it and stats can count its bytes.
#pragma once
#include "gl/gl.h"

#include <cstddef>
#include <string>

namespace rtlab::gl {

struct TextureDesc {
  // GL_TEXTURE_2D, GL_TEXTURE_2D_ARRAY (`layers` layers), GL_TEXTURE_3D (`depth` slices) or
  // GL_TEXTURE_CUBE_MAP (six faces, addressed as layers 0..5).
  GLenum target = GL_TEXTURE_2D;
  GLenum format = GL_RGBA8;        // sized internal format
  int width = 0, height = 0;
  int depth = 1;                   // GL_TEXTURE_3D only
  int layers = 1;                  // GL_TEXTURE_2D_ARRAY only
  int levels = 1;
  GLenum minFilter = GL_NEAREST, magFilter = GL_NEAREST;
  GLenum wrap = GL_CLAMP_TO_EDGE;
  bool depthCompare = false;       // GL_COMPARE_REF_TO_TEXTURE with GL_LEQUAL (shadow samplers)
  float border[4] = {1, 1, 1, 1};  // used with GL_CLAMP_TO_BORDER

  bool operator==(const TextureDesc& o) const;
  bool operator!=(const TextureDesc& o) const { return !(*this == o); }
  std::size_t bytes() const;       // estimate from the format's bits per texel, all layers, slices and levels
  // Size of mip level `level` (each dimension halves, at least 1; 3D textures halve their depth too).
  int widthAt(int level) const;
  int heightAt(int level) const;
  // Attachable layers of a level: array layers, 6 cube faces, or the 3D texture's depth at that level.
  int layersAt(int level) const;
  bool layered() const { return target != GL_TEXTURE_2D; }
};

// "2D", "2D array", "3D", "cube" (for messages).
const char* targetName(GLenum target);
// The first field in which two descriptions differ, e.g. "levels 1 vs 5"; "" when equal.
std::string descDifference(const TextureDesc& a, const TextureDesc& b);

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
