// The scene on the GPU: one vertex/index buffer pair and vertex array per mesh, material textures
// (sRGB where glTF says so, mipmapped), and draw helpers that set per-instance and per-material
// uniforms. Built when the scene is set; freed with it.
#pragma once
#include "gl/objects.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "scene/scene.h"

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
  std::size_t m_geometryBytes = 0, m_textureBytes = 0;
  bool m_hasTransparent = false;
};

} // namespace rtlab
