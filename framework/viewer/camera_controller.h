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
  // Places the camera so the box [lo, hi] fills the view, keeping the view direction.
  void frame(const glm::vec3& lo, const glm::vec3& hi);

  // Speeds: radians per pixel of drag, fraction of the target distance per wheel step, and
  // scene units per second of flying (scaled by the scene's size in frame()).
  float orbitSpeed = 0.005f, zoomStep = 0.1f, flySpeed = 2.0f;

private:
  Camera m_home, m_camera;
};

// The axis-aligned bounds of every instance of the scene, world space (lo > hi when empty).
void sceneBounds(const Scene& scene, glm::vec3& lo, glm::vec3& hi);

} // namespace rtlab
