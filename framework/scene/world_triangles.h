// Every instance's triangles in world space as one packed list, the CPU side of the GPU scene
// data that compute passes read (docs/scene-data.md "GPU scene data"). The layouts are std430
// arrays of 16-byte elements, uploaded as they are.
#pragma once
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace rtlab {

// The w component of a triangle: its material (bits 0-23) and flags (bit 31).
constexpr std::uint32_t kTriangleMaterialMask = 0x00FFFFFFu;
constexpr std::uint32_t kTriangleDefaultMaterial = kTriangleMaterialMask; // mesh.material == -1
constexpr std::uint32_t kTriangleTransparent = 0x80000000u;               // Instance::transparent

struct WorldTriangles {
  // Instance by instance in Scene::instances order, each its mesh's vertices in order.
  std::vector<glm::vec4> positions; // xyz world position, w = 1
  std::vector<glm::vec4> normals;   // xyz world unit normal (0 when degenerate), w = 0
  // Instance by instance, each its mesh's triangles in index order: xyz the vertices (indices
  // into positions), w the material index | kTriangleTransparent.
  std::vector<glm::uvec4> triangles;
  Bounds bounds; // of `positions` (invalid when there are none)
};

// Error(Internal) for a mesh index out of range or more than kTriangleMaterialMask materials (the
// loader and the built-in scenes never produce either).
WorldTriangles flattenWorldTriangles(const Scene& scene);

} // namespace rtlab
