#include "scene_geometry.h"

#include <algorithm>
#include <limits>

namespace rtlab::test {

static Bounds worldBoundsOf(const Scene& scene, const Instance& inst) {
  const Bounds& local = scene.meshes[std::size_t(inst.mesh)].bounds;
  Bounds out;
  for (int i = 0; i < 8; ++i) {
    glm::vec3 c((i & 1) ? local.max.x : local.min.x, (i & 2) ? local.max.y : local.min.y, (i & 4) ? local.max.z : local.min.z);
    out.extend(glm::vec3(inst.transform * glm::vec4(c, 1.0f)));
  }
  return out;
}

Bounds instanceBounds(const Scene& scene, const std::string& meshName) {
  for (const auto& inst : scene.instances)
    if (scene.meshes[std::size_t(inst.mesh)].name == meshName) return worldBoundsOf(scene, inst);
  return Bounds{};
}

bool segmentHitsBox(const glm::vec3& a, const glm::vec3& b, const Bounds& box) {
  const glm::vec3 d = b - a;
  float t0 = 1e-4f, t1 = 1.0f - 1e-4f;
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(d[axis]) < 1e-12f) {
      if (a[axis] < box.min[axis] || a[axis] > box.max[axis]) return false;
      continue;
    }
    float ta = (box.min[axis] - a[axis]) / d[axis];
    float tb = (box.max[axis] - a[axis]) / d[axis];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

bool segmentHitsAnyExcept(const Scene& scene, const glm::vec3& a, const glm::vec3& b, const std::string& except) {
  for (const auto& inst : scene.instances) {
    if (scene.meshes[std::size_t(inst.mesh)].name == except) continue;
    if (segmentHitsBox(a, b, worldBoundsOf(scene, inst))) return true;
  }
  return false;
}

} // namespace rtlab::test
