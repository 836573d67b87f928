// The camera's view of one frame: matrices and size, derived once per frame from the Camera.
#pragma once
#include "scene/scene.h"

#include <glm/glm.hpp>

namespace rtlab {

struct FrameView {
  int width = 0, height = 0;
  glm::mat4 view{1}, proj{1}, viewProj{1}, invViewProj{1};
  glm::vec3 cameraPosition{0};
  glm::vec3 cameraForward{0, 0, -1};
  float znear = 0.1f, zfar = 100.0f;
};

FrameView makeFrameView(const Camera& camera, int width, int height);

} // namespace rtlab
