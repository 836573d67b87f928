// The scene's signed distance volume (sdf_volume.h) as a 3D texture that a technique owns and lends
// to each frame (FrameGraph::importTexture), rebuilt only when what it depends on changed: the
// opaque geometry's content hash, the resolution or the padding. A light or camera move never
// rebuilds it; a scene set whose geometry hashes the same is a cache hit (counted).
#pragma once
#include "gl/program.h"
#include "gl/texture.h"
#include "techniques/common/sdf/sdf_volume.h"

#include <cstdint>
#include <string>

namespace rtlab {

class SdfTexture {
public:
  explicit SdfTexture(std::string label) : m_label(std::move(label)) {}

  // Call from Technique::sceneChanged: a geometry change makes the next update() compare hashes.
  void geometryChanged() { m_checkHash = true; }
  // Builds and uploads the volume if the geometry's hash, the resolution or the padding differ
  // from the last build (GL context current).
  void update(const Scene& scene, int resolution, int padding);

  gl::Texture& texture() { return m_texture; }
  const sdf::Grid& grid() const { return m_grid; }
  // Sets uSdfOrigin, uSdfSize, uSdfPadding (shaders/sdf/common/sdf_volume.glsl) and binds uSdf.
  void bind(gl::Program& program, int unit) const;

  int builds() const { return m_builds; }        // volumes built by this object
  int cacheHits() const { return m_cacheHits; }  // geometry changes that hashed the same
  double lastBuildMs() const { return m_buildMs; } // CPU distance queries of the last build
  std::size_t bytes() const { return m_texture ? m_texture.desc().bytes() : 0; }

private:
  std::string m_label;
  gl::Texture m_texture;
  sdf::Grid m_grid;
  bool m_checkHash = true;
  bool m_built = false;
  std::uint64_t m_hash = 0;
  int m_resolution = 0, m_padding = 0;
  int m_builds = 0, m_cacheHits = 0;
  double m_buildMs = 0.0;
};

} // namespace rtlab
