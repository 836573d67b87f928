// The shading point of the shadow terminator rule (docs/measuring.md, "The shading point"), the
// CPU twin of shaders/common/terminator.glsl, for the reference's ray hits (the camera-visible
// points come from the G-buffer, which applies the GLSL one): Hanika 2021, "Hacking the Shadow
// Terminator" (Ray Tracing Gems II, ch. 4). A point p of a flat triangle with barycentrics b is
// lifted onto the curved surface the vertex normals describe: for each vertex, p moved onto the
// vertex's tangent plane when it lies below it, the three moves blended with b.
#pragma once
#include <glm/glm.hpp>

#include <algorithm>

namespace rtlab::reference {

// positions: the triangle's vertices; normals: its unit vertex normals, on the side the point is
// seen from; b: barycentrics of p (summing to 1).
inline glm::vec3 terminatorPoint(const glm::vec3& p, const glm::vec3& b, const glm::vec3 positions[3],
                                 const glm::vec3 normals[3]) {
  glm::vec3 q = p;
  for (int i = 0; i < 3; ++i) q += (b[i] * std::max(glm::dot(positions[i] - p, normals[i]), 0.0f)) * normals[i];
  return q;
}

} // namespace rtlab::reference
