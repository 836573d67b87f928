// Geometry queries for picking test pixels from known world points instead of hand-tuned
// coordinates: instance bounds by mesh name, and segment/box intersection.
#pragma once
#include "scene/scene.h"

#include <string>

namespace rtlab::test {

// World-space bounds of the first instance whose mesh has this name; invalid Bounds if none.
Bounds instanceBounds(const Scene& scene, const std::string& meshName);
// True if the open segment a->b passes through the box (slab test), ignoring its ends.
bool segmentHitsBox(const glm::vec3& a, const glm::vec3& b, const Bounds& box);
// True if the segment a->b passes through any instance's bounds other than the named mesh.
bool segmentHitsAnyExcept(const Scene& scene, const glm::vec3& a, const glm::vec3& b, const std::string& except);

} // namespace rtlab::test
