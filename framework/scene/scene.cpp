// Scene queries, the framed default camera, clip-plane fitting and the default light.
#include "scene/scene.h"

#include <algorithm>
#include <cmath>

namespace rtlab {
namespace {

constexpr float kFrameMargin = 1.1f;        // the bounding sphere fills 1/1.1 of the vertical fov
constexpr float kMinNear = 0.01f;
constexpr float kMaxDepthRatio = 10000.0f;  // far / near
constexpr float kDefaultLightLux = 3.0f;
constexpr float kDefaultLightAngle = 0.5f;  // degrees, angular radius

} // namespace

Bounds Scene::worldBounds() const {
  Bounds out;
  for (const Instance& inst : instances) {
    if (inst.mesh < 0 || static_cast<size_t>(inst.mesh) >= meshes.size()) continue;
    const Bounds& b = meshes[static_cast<size_t>(inst.mesh)].bounds;
    if (!b.valid()) continue;
    for (int corner = 0; corner < 8; ++corner) {
      glm::vec3 p((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                  (corner & 4) ? b.max.z : b.min.z);
      out.extend(glm::vec3(inst.transform * glm::vec4(p, 1.0f)));
    }
  }
  return out;
}

bool Scene::hasTransparency() const {
  return std::any_of(instances.begin(), instances.end(),
                     [](const Instance& i) { return i.transparent; });
}

bool Scene::hasAreaLight() const {
  return std::any_of(lights.begin(), lights.end(),
                     [](const Light& l) { return l.type == LightType::Rect; });
}

Camera frameBounds(const Bounds& bounds, float fovYDegrees) {
  Camera camera;
  camera.fovY = fovYDegrees;
  if (!bounds.valid()) return camera;
  const glm::vec3 center = bounds.center();
  const float radius = std::max(bounds.radius(), 1e-3f);
  const float halfFov = glm::radians(std::clamp(fovYDegrees, 1.0f, 179.0f)) * 0.5f;
  const float distance = kFrameMargin * radius / std::sin(halfFov);
  camera.target = center;
  camera.position = center + glm::normalize(glm::vec3(0.0f, 0.35f, 1.0f)) * distance;
  camera.up = glm::vec3(0, 1, 0);
  fitClipPlanes(camera, bounds);
  return camera;
}

void fitClipPlanes(Camera& camera, const Bounds& bounds) {
  if (!bounds.valid()) return;
  const float radius = std::max(bounds.radius(), 1e-3f);
  const float distance = glm::length(bounds.center() - camera.position);
  const float zfar = (distance + radius) * 1.05f + 0.01f;
  float znear = (distance - radius) * 0.9f;
  znear = std::max({znear, zfar / kMaxDepthRatio, kMinNear});
  camera.znear = znear;
  camera.zfar = std::max(zfar, znear * 2.0f);
}

Light defaultLight(const Bounds& bounds) {
  Light light;
  light.name = "default";
  light.type = LightType::Directional;
  light.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
  light.intensity = kDefaultLightLux;
  light.angle = kDefaultLightAngle;
  if (bounds.valid()) {
    // Not used for shading; a sensible place for tools that want a light position.
    light.position = bounds.center() - light.direction * (2.0f * std::max(bounds.radius(), 1.0f));
  }
  return light;
}

} // namespace rtlab
