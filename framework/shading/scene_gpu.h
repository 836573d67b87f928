// The scene on the GPU: one vertex/index buffer pair and vertex array per mesh, material textures
// (sRGB where glTF says so, mipmapped), and draw helpers that set per-instance and per-material
// uniforms. Built when the scene is set; freed with it. The world-space triangle buffers for
// compute passes (scene_triangles_gpu.h) are built on the first request only.
#pragma once
#include "gl/objects.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "scene/scene.h"
#include "shading/scene_triangles_gpu.h"

#include <memory>
#include <vector>

namespace rtlab {

class SceneGpu {
public:
  explicit SceneGpu(const Scene& scene);

  enum class Filter { Opaque, Transparent, All };
  // Draws the instances that pass the filter. Sets uModel and uNormalMatrix on `program`; with
  // `materials`, also binds the material textures (units 0-4) and sets the material uniforms.
  // Transparent instances are drawn back to front from `eye`.
  void draw(gl::Program& program, Filter filter, bool materials, const glm::vec3& eye = glm::vec3(0)) const;

  // The scene's triangles in world space for compute shaders (docs/scene-data.md): built and
  // uploaded on the first call (the GL context must be current), then kept with this SceneGpu,
  // which the renderer replaces when the scene is set, so once per geometry change.
  const SceneTrianglesGpu& triangles();
  // triangles().bind(firstBinding): the blocks of shaders/common/scene_triangles.glsl.
  void bindTriangles(GLuint firstBinding = kSceneTrianglesBinding) { triangles().bind(firstBinding); }
  // Bytes of the triangle buffers; 0 until triangles() was called.
  std::size_t triangleBytes() const { return m_triangles ? m_triangles->bytes() : 0; }

  std::size_t geometryBytes() const { return m_geometryBytes; }
  std::size_t textureBytes() const { return m_textureBytes; }
  bool hasTransparent() const { return m_hasTransparent; }

private:
  struct MeshGpu {
    gl::VertexArray vao;
    gl::Buffer vertices, indices;
    GLsizei indexCount = 0;
  };
  void bindMaterial(gl::Program& program, int material) const;
  void drawInstance(gl::Program& program, const Instance& inst, bool materials) const;

  const Scene& m_scene;
  std::vector<MeshGpu> m_meshes;
  std::vector<gl::Texture> m_textures;
  gl::Texture m_white, m_flatNormal;
  std::unique_ptr<SceneTrianglesGpu> m_triangles;
  std::size_t m_geometryBytes = 0, m_textureBytes = 0;
  bool m_hasTransparent = false;
};

} // namespace rtlab
