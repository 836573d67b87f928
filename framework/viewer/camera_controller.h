// Interactive camera for `rtlab view` (GL-free, unit-tested): orbit about the target with the
// left mouse button, pan with the right or middle button, zoom (dolly towards the target) with
// the wheel, WASD fly (Q/E down/up) along the view axes, reset to the scene's camera, and frame
// the scene's bounding box. The state is the scene's Camera (position, target, up, fov), so a
// bookmark or `camera.*` keys hold it exactly.
#pragma once
#include "scene/scene.h"

#include <glm/glm.hpp>

namespace rtlab {

struct CameraInput {
  glm::vec2 mouseDelta{0};  // pixels since the last frame, +x right, +y down
  bool orbit = false;       // left button held
  bool pan = false;         // right or middle button held
  float wheel = 0;          // scroll steps this frame (+: towards the target)
  glm::vec3 fly{0};         // -1..1 per axis: x right (D-A), y up (E-Q), z forward (W-S)
  bool fast = false;        // shift held
  float dt = 0;             // seconds since the last frame
  glm::ivec2 viewport{1, 1};
};

class CameraController {
public:
  // `home` is the camera reset() returns to (the scene's camera or the -set camera.* values).
  explicit CameraController(const Camera& home = {});
  void setHome(const Camera& home);
  const Camera& camera() const { return m_camera; }
  void setCamera(const Camera& camera);

  // Applies one frame of input; returns true if the camera moved.
  bool update(const CameraInput& input);
  void reset();
  // Turns the camera about the target, keeping its distance: yaw about the world's up axis
  // (positive: counterclockwise seen from above), pitch towards the pole (positive: up), both in
  // radians; the pitch stays within +-maxPitch. Mouse drags call it with -dx and +dy times
  // orbitSpeed, so the scene follows the mouse. Returns true if the camera moved.
  bool orbit(float yaw, float pitch);
  // Places the camera so the box [lo, hi] fills the view, keeping the view direction.
  void frame(const glm::vec3& lo, const glm::vec3& hi);

  // The viewport whose aspect frame() fits (update() records the input's viewport too).
  void setViewport(const glm::ivec2& viewport);

  // Speeds: radians per pixel of drag, fraction of the target distance per wheel step (used in
  // [0, 0.9]), and scene units per second of flying (scaled by the scene's size in frame()).
  float orbitSpeed = 0.005f, zoomStep = 0.1f, flySpeed = 2.0f;
  float fastFactor = 4.0f;   // fly speed multiplier while shift is held
  float minDistance = 1e-3f; // zoom stops this close to the target (scaled in frame())
  // Orbit keeps the pitch (elevation above the target's horizontal plane) within +-maxPitch,
  // radians, so the view never passes over a pole and flips.
  float maxPitch = glm::radians(89.0f);
  // update() undoes a step that would take the position or target beyond +-maxCoordinate on
  // any axis: the range of the `camera.position` and `camera.target` keys.
  float maxCoordinate = 1.0e5f;

private:
  Camera m_home, m_camera;
  glm::ivec2 m_viewport{1, 1};
};

// The axis-aligned bounds of every instance of the scene, world space (lo > hi when empty).
void sceneBounds(const Scene& scene, glm::vec3& lo, glm::vec3& hi);

} // namespace rtlab
