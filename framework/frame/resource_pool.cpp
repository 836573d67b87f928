#include "frame/resource_pool.h"

#include "shading/gpu_common.h"

#include <algorithm>

namespace rtlab {

gl::Texture& ResourcePool::acquire(const std::string& name, const gl::TextureDesc& desc) {
  auto it = m_textures.find(name);
  if (it != m_textures.end() && it->second.desc() == desc) return it->second;
  if (it != m_textures.end()) m_textures.erase(it);
  m_framebuffers.clear();
  return m_textures.emplace(name, gl::Texture(desc, name)).first->second;
}

void ResourcePool::releaseExcept(const std::vector<std::string>& keep) {
  for (auto it = m_textures.begin(); it != m_textures.end();) {
    if (std::find(keep.begin(), keep.end(), it->first) == keep.end()) {
      m_framebuffers.clear();
      it = m_textures.erase(it);
    } else {
      ++it;
    }
  }
}

gl::Texture* ResourcePool::find(const std::string& name) {
  auto it = m_textures.find(name);
  return it == m_textures.end() ? nullptr : &it->second;
}

const gl::Framebuffer& ResourcePool::framebuffer(const std::string& label, const std::vector<const gl::Texture*>& colors,
                                                const gl::Texture* depth, int layer) {
  std::string key = label + "|";
  for (const auto* c : colors) key += std::to_string(c->id()) + ",";
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string&&.
  key += "|";
  key += std::to_string(depth ? depth->id() : 0);
  key += "|";
  key += std::to_string(layer);
  auto it = m_framebuffers.find(key);
  if (it == m_framebuffers.end()) it = m_framebuffers.emplace(key, makeFramebuffer(label, colors, depth, layer)).first;
  return it->second;
}

std::vector<ResourcePool::Entry> ResourcePool::entries() const {
  std::vector<Entry> out;
  for (const auto& [name, tex] : m_textures) out.push_back(Entry{name, tex.desc().bytes()});
  return out;
}

std::size_t ResourcePool::totalBytes() const {
  std::size_t total = 0;
  for (const auto& [name, tex] : m_textures) total += tex.desc().bytes();
  return total;
}

} // namespace rtlab
