#include "shading/scene_triangles_gpu.h"

#include "scene/world_triangles.h"

#include <vector>

namespace rtlab {
namespace {

// std430 layout of the SceneTriangleInfo block (shaders/common/scene_triangles.glsl).
struct InfoBlock {
  glm::vec4 boundsMin{0.0f}, boundsMax{0.0f};
  std::uint32_t triangleCount = 0, vertexCount = 0, pad[2] = {0, 0};
};
static_assert(sizeof(InfoBlock) == 48);

// Immutable storage holding `data`; an empty array still gets 16 zero bytes (GL refuses a
// zero-sized buffer) and the block's array then reads as empty through the counts.
template <typename T>
std::size_t upload(const gl::Buffer& buffer, const std::vector<T>& data) {
  static_assert(sizeof(T) % 16 == 0, "std430 arrays of 16-byte elements");
  if (data.empty()) {
    const std::vector<std::uint8_t> zero(16, 0);
    glNamedBufferStorage(buffer.id(), GLsizeiptr(zero.size()), zero.data(), 0);
    return zero.size();
  }
  const std::size_t bytes = data.size() * sizeof(T);
  glNamedBufferStorage(buffer.id(), GLsizeiptr(bytes), data.data(), 0);
  return bytes;
}

} // namespace

SceneTrianglesGpu::SceneTrianglesGpu(const Scene& scene) {
  const WorldTriangles world = flattenWorldTriangles(scene);
  m_triangleCount = std::uint32_t(world.triangles.size());
  m_vertexCount = std::uint32_t(world.positions.size());
  m_bounds = world.bounds;
  InfoBlock info;
  if (m_bounds.valid()) {
    info.boundsMin = glm::vec4(m_bounds.min, 0.0f);
    info.boundsMax = glm::vec4(m_bounds.max, 0.0f);
  }
  info.triangleCount = m_triangleCount;
  info.vertexCount = m_vertexCount;
  m_bytes = upload(m_info, std::vector<InfoBlock>{info}) + upload(m_positions, world.positions) +
            upload(m_normals, world.normals) + upload(m_triangles, world.triangles);
}

void SceneTrianglesGpu::bind(GLuint first) const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, first + 0, m_info.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, first + 1, m_positions.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, first + 2, m_normals.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, first + 3, m_triangles.id());
}

} // namespace rtlab
