// The scene's world-space triangles in shader storage buffers, for compute passes that voxelize
// the scene or bake a distance field (docs/scene-data.md "GPU scene data"). Built by SceneGpu on
// the first request after a scene is set, so a frame whose techniques never ask holds 0 bytes.
// The four blocks match shaders/common/scene_triangles.glsl.
#pragma once
#include "gl/objects.h"
#include "scene/scene.h"

#include <cstddef>
#include <cstdint>

namespace rtlab {

// Default first binding of the four blocks (the GLSL include's SCENE_TRIANGLES_BINDING): 4..7,
// inside GL's guaranteed minimum of 8 storage-buffer bindings and clear of the low bindings.
constexpr GLuint kSceneTrianglesBinding = 4;

class SceneTrianglesGpu {
public:
  explicit SceneTrianglesGpu(const Scene& scene); // flattens (world_triangles.h) and uploads

  // Binds the blocks to first + 0 (info), + 1 (positions), + 2 (normals), + 3 (triangles).
  void bind(GLuint firstBinding = kSceneTrianglesBinding) const;

  std::uint32_t triangleCount() const { return m_triangleCount; }
  std::uint32_t vertexCount() const { return m_vertexCount; }
  const Bounds& bounds() const { return m_bounds; } // invalid when there are no vertices
  std::size_t bytes() const { return m_bytes; }
  const gl::Buffer& info() const { return m_info; }
  const gl::Buffer& positions() const { return m_positions; }
  const gl::Buffer& normals() const { return m_normals; }
  const gl::Buffer& triangles() const { return m_triangles; }

private:
  gl::Buffer m_info{"scene.triangles.info"}, m_positions{"scene.triangles.positions"},
      m_normals{"scene.triangles.normals"}, m_triangles{"scene.triangles.triangles"};
  std::uint32_t m_triangleCount = 0, m_vertexCount = 0;
  Bounds m_bounds;
  std::size_t m_bytes = 0;
};

} // namespace rtlab
