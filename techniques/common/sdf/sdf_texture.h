// The scene's signed distance volumes (sdf_volume.h) in one 3D texture that a technique owns and
// lends to each frame (FrameGraph::importTexture), rebuilt only when what they depend on changed:
// the opaque geometry's content hash, the layout, the resolution or the padding. A light or camera
// move never rebuilds them; a scene set whose geometry hashes the same is a cache hit (counted).
// Recent builds are also kept for the whole process (at most kSharedCacheBytes of distances), so a
// new SdfTexture for the same geometry and settings (the technique turned off and on in the viewer,
// another renderer in the same process: sweep points, tests) uploads them instead of building.
//
// Two layouts (techniques/sdf_shadow/README.md "The SDF"): Scene, one volume over the padded
// bounds of all opaque geometry; PerInstance, one volume per opaque instance over its own padded
// bounds (so a small object gets fine voxels however large the scene), packed side by side into the
// texture (an atlas). A scene with more opaque instances than kMaxVolumes, whose volumes would
// hold more than kMaxVoxels in all, or whose volumes do not fit GL_MAX_3D_TEXTURE_SIZE, gets the
// Scene layout instead (volumes() says 1; documented there).
#pragma once
#include "gl/program.h"
#include "gl/texture.h"
#include "techniques/common/sdf/sdf_volume.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rtlab {

class SdfTexture {
public:
  enum class Layout { Scene, PerInstance };
  // The most volumes a shader loops over (the length of its uniform arrays): SDF_MAX_VOLUMES in
  // shaders/sdf/common/sdf_volume.glsl, defined from this constant by the technique.
  static constexpr int kMaxVolumes = 16;
  // The most voxels the PerInstance volumes hold in all: what one Scene volume holds at most (a
  // cube at the largest resolution, 256^3), so neither layout builds or stores more than that.
  static constexpr std::size_t kMaxVoxels = std::size_t(256) * 256 * 256;
  // The distances the process-wide cache of recent builds keeps at most (the oldest go first).
  static constexpr std::size_t kSharedCacheBytes = std::size_t(128) << 20;
  // Empties that cache (tests that count builds start from it).
  static void clearSharedCache();

  explicit SdfTexture(std::string label) : m_label(std::move(label)) {}

  // Call from Technique::sceneChanged: a geometry change makes the next update() compare hashes.
  void geometryChanged() { m_checkHash = true; }
  // Builds and uploads the volumes if the geometry's hash, the layout, the resolution or the
  // padding differ from the last build (GL context current).
  void update(const Scene& scene, Layout layout, int resolution, int padding);

  gl::Texture& texture() { return m_texture; }
  // Sets the uniforms of shaders/sdf/common/sdf_volume.glsl (each volume's box, padding, voxel and
  // place in the texture; the union box) and binds uSdf.
  void bind(gl::Program& program, int unit) const;

  int volumes() const { return int(m_grids.size()); } // 1 for Scene and for the fallback
  int builds() const { return m_builds; }             // builds done by this object
  int cacheHits() const { return m_cacheHits; }       // geometry changes that hashed the same
  int sharedHits() const { return m_sharedHits; }     // builds taken from the process-wide cache
  double lastBuildMs() const { return m_buildMs; }    // CPU distance queries of the last build
  std::size_t voxels() const;                         // over the volumes (not the atlas' slack)
  std::size_t bytes() const { return m_texture ? m_texture.desc().bytes() : 0; }

private:
  void upload(const std::vector<sdf::Volume>& volumes, const std::vector<glm::ivec3>& offsets, glm::ivec3 size);

  std::string m_label;
  gl::Texture m_texture;
  std::vector<sdf::Grid> m_grids;
  // bind()'s uniforms, derived from the grids and their places once per upload: each volume's box
  // and padding, extent and voxel, first texel; the union box; the finest voxel.
  std::vector<glm::vec4> m_box, m_extent, m_texel;
  glm::vec3 m_unionOrigin{0.0f}, m_unionSize{0.0f};
  float m_finestVoxel = 1.0f;
  bool m_checkHash = true;
  bool m_built = false;
  std::uint64_t m_hash = 0;
  Layout m_layout = Layout::Scene;
  int m_resolution = 0, m_padding = 0;
  int m_builds = 0, m_cacheHits = 0, m_sharedHits = 0;
  double m_buildMs = 0.0;
};

// Whether volumes of `dims` may be PerInstance volumes: 1..kMaxVolumes of them, kMaxVoxels in all.
bool perInstanceAllowed(const std::vector<glm::ivec3>& dims);

// Places boxes of `dims` side by side in a texture no larger than `maxSize` on any axis: stacked
// along z into columns, a new column along x when the next one would pass maxSize. Returns each
// box's first texel and the texture's size in `size`; false when they do not fit.
bool packVolumes(const std::vector<glm::ivec3>& dims, int maxSize, std::vector<glm::ivec3>& offsets, glm::ivec3& size);

} // namespace rtlab
