// The viewer's camera: orbit, pan, dolly and fly on the scene's Camera (position, target, up,
// fovY), so the result is exactly what `camera.*` keys and bookmarks store.
#include "viewer/camera_controller.h"

#include <algorithm>
#include <cmath>

namespace rtlab {
namespace {

constexpr glm::vec3 kWorldUp{0, 1, 0};
constexpr float kFrameMargin = 1.05f; // frame() leaves 5% around the bounding sphere
constexpr float kMinRadius = 0.05f;

bool finite(const glm::vec2& v) {
  return std::isfinite(v.x) && std::isfinite(v.y);
}
bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The camera's orthonormal view axes; robust when position == target or forward is parallel to up.
struct Basis {
  glm::vec3 forward, right, up;
};

Basis viewBasis(const Camera& c) {
  Basis b;
  const glm::vec3 d = c.target - c.position;
  b.forward = glm::length(d) > 0 ? glm::normalize(d) : glm::vec3(0, 0, -1);
  glm::vec3 r = glm::cross(b.forward, c.up);
  if (glm::length(r) < 1e-6f) r = glm::cross(b.forward, std::abs(b.forward.y) < 0.9f ? kWorldUp : glm::vec3(0, 0, 1));
  b.right = glm::normalize(r);
  b.up = glm::cross(b.right, b.forward);
  return b;
}

} // namespace

CameraController::CameraController(const Camera& home) : m_home(home), m_camera(home) {}

void CameraController::setHome(const Camera& home) {
  m_home = home;
}
void CameraController::setCamera(const Camera& camera) {
  m_camera = camera;
}
void CameraController::reset() {
  m_camera = m_home;
}

void CameraController::setViewport(const glm::ivec2& viewport) {
  if (viewport.x > 0 && viewport.y > 0) m_viewport = viewport;
}

bool CameraController::orbit(float yaw, float pitch) {
  const glm::vec3 offset = m_camera.position - m_camera.target;
  const float distance = glm::length(offset);
  if (!(distance > 0) || !std::isfinite(yaw) || !std::isfinite(pitch)) return false;
  const glm::vec3 dir = offset / distance;
  // Spherical angles of the camera seen from the target: azimuth about +y from +z, elevation.
  const float azimuth = std::atan2(dir.x, dir.z) + yaw;
  float elevation = std::asin(std::clamp(dir.y, -1.0f, 1.0f)) + pitch;
  const float limit = std::clamp(maxPitch, 0.0f, glm::radians(89.9f));
  elevation = std::clamp(elevation, -limit, limit);
  const glm::vec3 next{std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                       std::cos(elevation) * std::cos(azimuth)};
  const glm::vec3 before = m_camera.position;
  m_camera.position = m_camera.target + next * distance;
  return m_camera.position != before;
}

bool CameraController::update(const CameraInput& in) {
  setViewport(in.viewport);
  const Camera before = m_camera;
  // A step that would take the camera out of +-maxCoordinate is undone, so the camera always
  // fits the `camera.*` keys' range and stays finite however far one zooms out or flies.
  Camera lastGood = m_camera;
  auto keepInside = [&] {
    const float m = maxCoordinate;
    auto inside = [m](const glm::vec3& p) {
      return finite(p) && glm::all(glm::lessThanEqual(glm::abs(p), glm::vec3(m)));
    };
    if (!inside(m_camera.position) || !inside(m_camera.target)) m_camera = lastGood;
    lastGood = m_camera;
  };
  if (in.orbit && finite(in.mouseDelta)) orbit(-in.mouseDelta.x * orbitSpeed, in.mouseDelta.y * orbitSpeed);
  keepInside();

  if (in.pan && finite(in.mouseDelta) && in.viewport.y > 0) {
    // One pixel at the target's distance spans 2 d tan(fov/2) / height scene units, so the point
    // under the cursor at that depth follows the mouse.
    const Basis b = viewBasis(m_camera);
    const float distance = glm::length(m_camera.target - m_camera.position);
    const float perPixel = 2.0f * distance * std::tan(glm::radians(m_camera.fovY) * 0.5f) / float(in.viewport.y);
    const glm::vec3 move = (-in.mouseDelta.x * b.right + in.mouseDelta.y * b.up) * perPixel;
    m_camera.position += move;
    m_camera.target += move;
  }
  keepInside();

  if (in.wheel != 0 && std::isfinite(in.wheel)) {
    // Each step scales the distance by (1 - zoomStep): geometric, so the target is never reached.
    const glm::vec3 offset = m_camera.position - m_camera.target;
    const float distance = glm::length(offset);
    if (distance > 0) {
      const float step = std::clamp(zoomStep, 0.0f, 0.9f);
      float next = distance * std::pow(1.0f - step, in.wheel);
      if (in.wheel > 0) next = std::max(next, std::min(distance, minDistance));
      if (std::isfinite(next) && next > 0) m_camera.position = m_camera.target + offset * (next / distance);
    }
  }
  keepInside();

  if (in.dt > 0 && std::isfinite(in.dt) && finite(in.fly) && glm::length(in.fly) > 0) {
    const Basis b = viewBasis(m_camera);
    glm::vec3 f = in.fly;
    if (glm::length(f) > 1) f = glm::normalize(f); // diagonals are not faster
    const float speed = flySpeed * (in.fast ? fastFactor : 1.0f);
    const glm::vec3 move = (f.x * b.right + f.y * b.up + f.z * b.forward) * speed * in.dt;
    m_camera.position += move;
    m_camera.target += move;
  }
  keepInside();
  return m_camera.position != before.position || m_camera.target != before.target;
}

void CameraController::frame(const glm::vec3& lo, const glm::vec3& hi) {
  if (!finite(lo) || !finite(hi) || lo.x > hi.x || lo.y > hi.y || lo.z > hi.z) return; // empty
  const glm::vec3 center = (lo + hi) * 0.5f;
  // A point (or tiny) box still gets a camera in front of fitClipPlanes' 0.01 near-plane floor.
  const float radius = std::max(0.5f * glm::length(hi - lo), kMinRadius);
  glm::vec3 dir = m_camera.position - m_camera.target;
  dir = glm::length(dir) > 0 ? glm::normalize(dir) : glm::normalize(glm::vec3(0.0f, 0.35f, 1.0f));
  // The sphere fits a cone of half-angle a at distance radius / sin(a); use the narrower of the
  // vertical and horizontal half-angles.
  const float halfY = glm::radians(std::clamp(m_camera.fovY, 1.0f, 179.0f)) * 0.5f;
  const float aspect = float(m_viewport.x) / float(m_viewport.y);
  const float halfX = std::atan(std::tan(halfY) * aspect);
  const float distance = kFrameMargin * radius / std::sin(std::min(halfY, halfX));
  m_camera.target = center;
  m_camera.position = center + dir * distance;
  Bounds bounds;
  bounds.extend(lo);
  bounds.extend(hi);
  fitClipPlanes(m_camera, bounds);
  flySpeed = radius; // crosses the scene in about two seconds
  minDistance = radius * 1e-3f;
}

void sceneBounds(const Scene& scene, glm::vec3& lo, glm::vec3& hi) {
  const Bounds b = scene.worldBounds();
  lo = b.min;
  hi = b.max;
}

} // namespace rtlab
