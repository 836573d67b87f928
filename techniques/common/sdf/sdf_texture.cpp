#include "techniques/common/sdf/sdf_texture.h"

#include <algorithm>
#include <deque>
#include <memory>
#include <mutex>

namespace rtlab {
namespace {

// What one update() built: the volumes and their places in the texture.
struct Built {
  std::vector<sdf::Volume> volumes;
  std::vector<glm::ivec3> offsets;
  glm::ivec3 size{0};
  std::size_t bytes() const {
    std::size_t n = 0;
    for (const sdf::Volume& v : volumes) n += v.distance.size() * sizeof(float);
    return n;
  }
};

struct SharedKey {
  std::uint64_t hash;
  SdfTexture::Layout layout;
  int resolution, padding, maxSize;
  bool operator==(const SharedKey&) const = default;
};

// The process-wide cache of recent builds, newest last, at most kSharedCacheBytes in all.
struct SharedCache {
  std::mutex mutex;
  std::deque<std::pair<SharedKey, std::shared_ptr<const Built>>> entries;

  std::shared_ptr<const Built> find(const SharedKey& key) {
    std::lock_guard lock(mutex);
    for (const auto& [k, built] : entries)
      if (k == key) return built;
    return nullptr;
  }
  void add(const SharedKey& key, std::shared_ptr<const Built> built) {
    std::lock_guard lock(mutex);
    if (built->bytes() > SdfTexture::kSharedCacheBytes) return;
    entries.emplace_back(key, std::move(built));
    std::size_t total = 0;
    for (const auto& e : entries) total += e.second->bytes();
    while (total > SdfTexture::kSharedCacheBytes) {
      total -= entries.front().second->bytes();
      entries.pop_front();
    }
  }
};

SharedCache& sharedCache() {
  static SharedCache cache;
  return cache;
}

} // namespace

void SdfTexture::clearSharedCache() {
  std::lock_guard lock(sharedCache().mutex);
  sharedCache().entries.clear();
}

bool packVolumes(const std::vector<glm::ivec3>& dims, int maxSize, std::vector<glm::ivec3>& offsets, glm::ivec3& size) {
  offsets.clear();
  size = glm::ivec3(0);
  int columnX = 0, columnWidth = 0, z = 0;
  for (const glm::ivec3& d : dims) {
    if (d.x > maxSize || d.y > maxSize || d.z > maxSize) return false;
    if (z + d.z > maxSize) { // a new column
      columnX += columnWidth;
      columnWidth = 0;
      z = 0;
    }
    offsets.emplace_back(columnX, 0, z);
    columnWidth = std::max(columnWidth, d.x);
    z += d.z;
    size = glm::max(size, glm::ivec3(columnX + columnWidth, d.y, z));
  }
  return size.x <= maxSize;
}

bool perInstanceAllowed(const std::vector<glm::ivec3>& dims) {
  if (dims.empty() || dims.size() > std::size_t(SdfTexture::kMaxVolumes)) return false;
  std::size_t voxels = 0;
  for (const glm::ivec3& d : dims)
    voxels += std::size_t(d.x) * std::size_t(d.y) * std::size_t(d.z);
  return voxels <= SdfTexture::kMaxVoxels;
}

void SdfTexture::update(const Scene& scene, Layout layout, int resolution, int padding) {
  const bool sameSize = m_built && layout == m_layout && resolution == m_resolution && padding == m_padding;
  if (sameSize && !m_checkHash) return;
  const std::uint64_t hash = sdf::geometryHash(scene);
  m_checkHash = false;
  if (sameSize && hash == m_hash) {
    ++m_cacheHits;
    return;
  }
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maxSize);
  const SharedKey key{hash, layout, resolution, padding, int(maxSize)};
  std::shared_ptr<const Built> built = sharedCache().find(key);
  if (built) {
    upload(built->volumes, built->offsets, built->size);
    m_buildMs = 0.0; // nothing was built
    ++m_sharedHits;
  } else {
    auto fresh = std::make_shared<Built>();
    const sdf::TriangleDistance field(scene);
    if (layout == Layout::PerInstance) {
      std::vector<glm::ivec3> dims;
      for (std::size_t i = 0; i < field.partCount() && i <= std::size_t(kMaxVolumes); ++i)
        dims.push_back(sdf::fitGrid(field.partBounds(i), resolution, padding).dims);
      if (perInstanceAllowed(dims) && packVolumes(dims, maxSize, fresh->offsets, fresh->size))
        fresh->volumes = sdf::buildInstanceVolumes(field, resolution, padding);
    }
    if (fresh->volumes.empty()) { // the Scene layout, or the per-instance fallback (none, too many, too large)
      fresh->volumes.push_back(sdf::buildVolume(field, resolution, padding));
      fresh->offsets = {glm::ivec3(0)};
      fresh->size = fresh->volumes[0].grid.dims;
    }
    upload(fresh->volumes, fresh->offsets, fresh->size);
    sharedCache().add(key, std::move(fresh));
    ++m_builds;
  }
  m_hash = hash;
  m_layout = layout;
  m_resolution = resolution;
  m_padding = padding;
  m_built = true;
}

void SdfTexture::upload(const std::vector<sdf::Volume>& volumes, const std::vector<glm::ivec3>& offsets,
                        glm::ivec3 size) {
  gl::TextureDesc d;
  d.target = GL_TEXTURE_3D;
  // 16-bit floats: 11 significant bits keep distances near surfaces (where the march decides)
  // to well below the hit threshold; techniques/sdf_shadow/README.md "The SDF" has the measurement.
  d.format = GL_R16F;
  d.width = size.x;
  d.height = size.y;
  d.depth = size.z;
  d.minFilter = d.magFilter = GL_LINEAR;
  d.wrap = GL_CLAMP_TO_EDGE;
  if (!m_texture || m_texture.desc() != d) m_texture = gl::Texture(d, m_label);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  m_grids.clear();
  m_box.clear();
  m_extent.clear();
  m_texel.clear();
  m_buildMs = 0.0;
  Bounds all;
  for (std::size_t i = 0; i < volumes.size(); ++i) {
    const sdf::Volume& v = volumes[i];
    const glm::ivec3 o = offsets[i];
    glTextureSubImage3D(m_texture.id(), 0, o.x, o.y, o.z, v.grid.dims.x, v.grid.dims.y, v.grid.dims.z, GL_RED, GL_FLOAT,
                        v.distance.data());
    m_grids.push_back(v.grid);
    m_box.emplace_back(v.grid.origin, v.grid.padding);
    m_extent.emplace_back(v.grid.size(), v.grid.voxel);
    m_texel.emplace_back(glm::vec3(o), 0.0f);
    all.extend(v.grid.origin);
    all.extend(v.grid.origin + v.grid.size());
    m_finestVoxel = i == 0 ? v.grid.voxel : std::min(m_finestVoxel, v.grid.voxel);
    m_buildMs += v.buildMs;
  }
  m_unionOrigin = all.min;
  m_unionSize = all.max - all.min;
}

std::size_t SdfTexture::voxels() const {
  std::size_t n = 0;
  for (const sdf::Grid& g : m_grids)
    n += g.count();
  return n;
}

void SdfTexture::bind(gl::Program& program, int unit) const {
  m_texture.bind(GLuint(unit));
  program.set("uSdf", unit)
      .set("uSdfCount", int(m_grids.size()))
      .set("uSdfBox", m_box)
      .set("uSdfExtent", m_extent)
      .set("uSdfTexel", m_texel)
      .set("uSdfOrigin", m_unionOrigin)
      .set("uSdfSize", m_unionSize)
      .set("uSdfVoxel", m_finestVoxel);
}

} // namespace rtlab
