// Frame-graph textures by name. A texture survives from frame to frame while some kept pass keeps
// writing it with the same description; anything not written in a frame is released at compile().
#pragma once
#include "gl/texture.h"

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace rtlab {

class ResourcePool {
public:
  // Makes the named texture exist with this description (reallocating if it changed).
  gl::Texture& acquire(const std::string& name, const gl::TextureDesc& desc);
  // Releases every texture whose name is not in `keep`.
  void releaseExcept(const std::vector<std::string>& keep);
  void releaseAll() { m_textures.clear(); }
  bool has(const std::string& name) const { return m_textures.count(name) != 0; }
  gl::Texture* find(const std::string& name);

  struct Entry {
    std::string name;
    std::size_t bytes;
  };
  std::vector<Entry> entries() const;
  std::size_t totalBytes() const;

private:
  std::map<std::string, gl::Texture> m_textures;
};

} // namespace rtlab
