// Frame-graph resources by name: textures and buffers (docs/frame-graph.md "Resources"). A resource
// survives from frame to frame while some kept pass keeps writing it with the same description;
// anything not written in a frame is released at compile().
#pragma once
#include "gl/buffer.h"
#include "gl/framebuffer.h"
#include "gl/objects.h"
#include "gl/texture.h"

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace rtlab {

class ResourcePool {
public:
  // Makes the named texture or buffer exist with this description (reallocating if it changed).
  gl::Texture& acquire(const std::string& name, const gl::TextureDesc& desc);
  gl::BufferObject& acquire(const std::string& name, const gl::BufferDesc& desc);
  // Releases every resource whose name is not in `keep`.
  void releaseExcept(const std::vector<std::string>& keep);
  void releaseAll() {
    m_framebuffers.clear();
    m_textures.clear();
    m_buffers.clear();
    m_imports.clear();
    m_importIds.clear();
  }
  bool has(const std::string& name) const {
    return m_textures.count(name) != 0 || m_buffers.count(name) != 0 || m_imports.count(name) != 0;
  }
  gl::Texture* find(const std::string& name);
  gl::BufferObject* findBuffer(const std::string& name);

  // Imported resources (docs/frame-graph.md "Imported resources"): objects a technique owns and
  // lends to this frame's graph under a name. find()/findBuffer() see them; entries() does not
  // count them (the technique reports them in ownedBytes()). Set once per frame by compile();
  // a changed object under a name drops the cached framebuffers.
  struct Import {
    gl::Texture* texture = nullptr;
    gl::BufferObject* buffer = nullptr;
  };
  void setImports(const std::map<std::string, Import>& imports);

  // A framebuffer over pool textures, cached until any pool texture is allocated or released
  // (GL reuses texture names, so a cached framebuffer must not outlive its attachments).
  const gl::Framebuffer& framebuffer(const std::string& label, const std::vector<gl::Attachment>& colors,
                                     const gl::Attachment& depth = {});
  const gl::Framebuffer& framebuffer(const std::string& label, const std::vector<const gl::Texture*>& colors,
                                     const gl::Texture* depth = nullptr, int layer = -1);

  // Textures and buffers by name, with their bytes.
  struct Entry {
    std::string name;
    std::size_t bytes;
  };
  std::vector<Entry> entries() const;
  std::size_t totalBytes() const;

private:
  std::map<std::string, gl::Texture> m_textures;
  std::map<std::string, gl::BufferObject> m_buffers;
  std::map<std::string, gl::Framebuffer> m_framebuffers;
  std::map<std::string, Import> m_imports;
  std::map<std::string, GLuint> m_importIds; // object names of the last frame's imports
};

} // namespace rtlab
