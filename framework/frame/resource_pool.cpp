#include "frame/resource_pool.h"

#include <algorithm>

namespace rtlab {

gl::Texture& ResourcePool::acquire(const std::string& name, const gl::TextureDesc& desc) {
  auto it = m_textures.find(name);
  if (it != m_textures.end() && it->second.desc() == desc) return it->second;
  if (it != m_textures.end()) m_textures.erase(it);
  return m_textures.emplace(name, gl::Texture(desc, name)).first->second;
}

void ResourcePool::releaseExcept(const std::vector<std::string>& keep) {
  for (auto it = m_textures.begin(); it != m_textures.end();) {
    if (std::find(keep.begin(), keep.end(), it->first) == keep.end()) it = m_textures.erase(it);
    else ++it;
  }
}

gl::Texture* ResourcePool::find(const std::string& name) {
  auto it = m_textures.find(name);
  return it == m_textures.end() ? nullptr : &it->second;
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
