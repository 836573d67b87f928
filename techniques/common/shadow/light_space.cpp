#include "techniques/common/shadow/light_space.h"

#include "util/error.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab {
namespace {

constexpr float kMaxSpotFovDegrees = 120.0f;

glm::vec3 anyPerpendicularUp(const glm::vec3& dir) {
  return std::abs(dir.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
}

// Near/far that enclose the bounds seen from `eye`, keeping near well away from zero.
void fitRange(const glm::vec3& eye, const Bounds& b, float& znear, float& zfar) {
  float farthest = 0.0f;
  for (int i = 0; i < 8; ++i) {
    glm::vec3 c((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
    farthest = std::max(farthest, glm::length(c - eye));
  }
  zfar = std::max(farthest * 1.01f, 1e-3f);
  // Near plane at 90% of the distance to the bounding box (0 inside it), but never closer than
  // far/2000: perspective depth precision is set by far/near.
  const glm::vec3 outside = glm::max(glm::max(b.min - eye, eye - b.max), glm::vec3(0.0f));
  znear = std::max(glm::length(outside) * 0.9f, zfar / 2000.0f);
}

} // namespace

LightSpace computeLightSpace(const Light& light, const Bounds& bounds, int resolution) {
  LightSpace ls;
  ls.direction = glm::normalize(light.direction);
  ls.position = light.position;
  const float res = float(std::max(resolution, 1));
  if (light.type == LightType::Rect)
    usageError("light 0 is rectangular: shadow maps support directional, spot and point lights");
  if (light.type == LightType::Directional) {
    const float r = std::max(bounds.radius(), 1e-3f) * 1.01f;
    const glm::vec3 center = bounds.center();
    const glm::vec3 eye = center - ls.direction * (2.0f * r);
    const glm::mat4 view = glm::lookAt(eye, center, anyPerpendicularUp(ls.direction));
    ls.znear = r;
    ls.zfar = 3.0f * r;
    ls.viewProj[0] = glm::ortho(-r, r, -r, r, ls.znear, ls.zfar) * view;
    ls.projection = LightProjection::Orthographic;
    ls.texelScale = 2.0f * r / res;
    ls.position = eye;
    return ls;
  }
  fitRange(light.position, bounds, ls.znear, ls.zfar);
  const float fov = 2.0f * glm::degrees(light.outerConeAngle) + 2.0f;
  if (light.type == LightType::Spot && fov <= kMaxSpotFovDegrees) {
    const glm::mat4 view = glm::lookAt(light.position, light.position + ls.direction, anyPerpendicularUp(ls.direction));
    ls.viewProj[0] = glm::perspective(glm::radians(fov), 1.0f, ls.znear, ls.zfar) * view;
    ls.projection = LightProjection::Perspective;
    ls.texelScale = 2.0f * std::tan(glm::radians(fov) * 0.5f) / res;
    return ls;
  }
  static const glm::vec3 kDirs[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  static const glm::vec3 kUps[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  const glm::mat4 proj = glm::perspective(glm::radians(90.0f), 1.0f, ls.znear, ls.zfar);
  for (int f = 0; f < 6; ++f) ls.viewProj[f] = proj * glm::lookAt(light.position, light.position + kDirs[f], kUps[f]);
  ls.projection = LightProjection::Cube;
  ls.texelScale = 2.0f / res;
  return ls;
}

} // namespace rtlab
