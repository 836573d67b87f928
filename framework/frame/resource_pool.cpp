#include "frame/resource_pool.h"

#include <algorithm>

namespace rtlab {

gl::Texture& ResourcePool::acquire(const std::string& name, const gl::TextureDesc& desc) {
  auto it = m_textures.find(name);
  if (it != m_textures.end() && it->second.desc() == desc) return it->second;
  if (it != m_textures.end()) m_textures.erase(it);
  m_buffers.erase(name);
  m_framebuffers.clear();
  return m_textures.emplace(name, gl::Texture(desc, name)).first->second;
}

gl::BufferObject& ResourcePool::acquire(const std::string& name, const gl::BufferDesc& desc) {
  auto it = m_buffers.find(name);
  if (it != m_buffers.end() && it->second.desc() == desc) return it->second;
  if (it != m_buffers.end()) m_buffers.erase(it);
  if (m_textures.erase(name) != 0) m_framebuffers.clear();
  return m_buffers.emplace(name, gl::BufferObject(desc, name)).first->second;
}

void ResourcePool::releaseExcept(const std::vector<std::string>& keep) {
  auto kept = [&](const std::string& name) { return std::find(keep.begin(), keep.end(), name) != keep.end(); };
  for (auto it = m_textures.begin(); it != m_textures.end();) {
    if (!kept(it->first)) {
      m_framebuffers.clear();
      it = m_textures.erase(it);
    } else {
      ++it;
    }
  }
  for (auto it = m_buffers.begin(); it != m_buffers.end();) it = kept(it->first) ? std::next(it) : m_buffers.erase(it);
}

gl::Texture* ResourcePool::find(const std::string& name) {
  auto it = m_textures.find(name);
  if (it != m_textures.end()) return &it->second;
  auto imported = m_imports.find(name);
  return imported == m_imports.end() ? nullptr : imported->second.texture;
}

void ResourcePool::setImports(const std::map<std::string, Import>& imports) {
  std::map<std::string, GLuint> ids;
  for (const auto& [name, i] : imports) ids[name] = i.texture ? i.texture->id() : i.buffer->id();
  // A framebuffer may hold an imported texture; GL reuses names, so a new object under a name (or a
  // name gone) must not meet a cached framebuffer of the old one.
  if (ids != m_importIds) m_framebuffers.clear();
  m_importIds = std::move(ids);
  m_imports = imports;
}

gl::BufferObject* ResourcePool::findBuffer(const std::string& name) {
  auto it = m_buffers.find(name);
  if (it != m_buffers.end()) return &it->second;
  auto imported = m_imports.find(name);
  return imported == m_imports.end() ? nullptr : imported->second.buffer;
}

const gl::Framebuffer& ResourcePool::framebuffer(const std::string& label, const std::vector<gl::Attachment>& colors,
                                                const gl::Attachment& depth) {
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string&&.
  std::string key = label;
  auto add = [&](const gl::Attachment& a) {
    key += "|";
    key += std::to_string(a.texture ? a.texture->id() : 0);
    key += ":";
    key += std::to_string(a.level);
    key += ":";
    key += std::to_string(a.layer);
  };
  for (const auto& c : colors) add(c);
  key += "|depth";
  add(depth);
  auto it = m_framebuffers.find(key);
  if (it == m_framebuffers.end()) it = m_framebuffers.emplace(key, gl::makeFramebuffer(label, colors, depth)).first;
  return it->second;
}

const gl::Framebuffer& ResourcePool::framebuffer(const std::string& label, const std::vector<const gl::Texture*>& colors,
                                                const gl::Texture* depth, int layer) {
  std::vector<gl::Attachment> attachments;
  for (const gl::Texture* c : colors) attachments.push_back(gl::Attachment{c, 0, -1});
  return framebuffer(label, attachments, gl::Attachment{depth, 0, depth ? layer : -1});
}

std::vector<ResourcePool::Entry> ResourcePool::entries() const {
  std::vector<Entry> out;
  for (const auto& [name, tex] : m_textures) out.push_back(Entry{name, tex.desc().bytes()});
  for (const auto& [name, buf] : m_buffers) out.push_back(Entry{name, buf.desc().bytes});
  std::sort(out.begin(), out.end(), [](const Entry& a, const Entry& b) { return a.name < b.name; });
  return out;
}

std::size_t ResourcePool::totalBytes() const {
  std::size_t total = 0;
  for (const auto& e : entries()) total += e.bytes;
  return total;
}

} // namespace rtlab
