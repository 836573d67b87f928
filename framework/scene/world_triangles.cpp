#include "scene/world_triangles.h"

#include "util/error.h"

#include <string>

namespace rtlab {

WorldTriangles flattenWorldTriangles(const Scene& scene) {
  if (scene.materials.size() >= kTriangleMaterialMask)
    throw Error(ExitCode::Internal, "scene has " + std::to_string(scene.materials.size()) +
                                        " materials; triangle data holds at most " + std::to_string(kTriangleMaterialMask - 1));
  WorldTriangles out;
  std::size_t vertexTotal = 0, triangleTotal = 0;
  for (const Instance& inst : scene.instances) {
    if (inst.mesh < 0 || std::size_t(inst.mesh) >= scene.meshes.size())
      throw Error(ExitCode::Internal, "instance names mesh " + std::to_string(inst.mesh) + " of " +
                                          std::to_string(scene.meshes.size()));
    vertexTotal += scene.meshes[std::size_t(inst.mesh)].vertices.size();
    triangleTotal += scene.meshes[std::size_t(inst.mesh)].indices.size() / 3;
  }
  out.positions.reserve(vertexTotal);
  out.normals.reserve(vertexTotal);
  out.triangles.reserve(triangleTotal);
  for (const Instance& inst : scene.instances) {
    const Mesh& mesh = scene.meshes[std::size_t(inst.mesh)];
    const auto base = std::uint32_t(out.positions.size());
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(inst.transform)));
    for (const Vertex& v : mesh.vertices) {
      const glm::vec3 p = glm::vec3(inst.transform * glm::vec4(v.position, 1.0f));
      const glm::vec3 n = normalMatrix * v.normal;
      const float len = glm::length(n);
      out.positions.emplace_back(p, 1.0f);
      out.normals.emplace_back(len > 0.0f ? n / len : glm::vec3(0.0f), 0.0f);
      out.bounds.extend(p);
    }
    const bool known = mesh.material >= 0 && std::size_t(mesh.material) < scene.materials.size();
    const std::uint32_t w = (known ? std::uint32_t(mesh.material) : kTriangleDefaultMaterial) |
                            (inst.transparent ? kTriangleTransparent : 0u);
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      const std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
      if (a >= mesh.vertices.size() || b >= mesh.vertices.size() || c >= mesh.vertices.size())
        throw Error(ExitCode::Internal, "mesh '" + mesh.name + "' has an index out of range");
      out.triangles.emplace_back(base + a, base + b, base + c, w);
    }
  }
  return out;
}

} // namespace rtlab
