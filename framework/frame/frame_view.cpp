#include "frame/frame_view.h"

#include <glm/gtc/matrix_transform.hpp>

namespace rtlab {

FrameView makeFrameView(const Camera& camera, int width, int height) {
  FrameView v;
  v.width = width;
  v.height = height;
  v.znear = camera.znear;
  v.zfar = camera.zfar;
  v.cameraPosition = camera.position;
  v.cameraForward = glm::normalize(camera.target - camera.position);
  v.view = glm::lookAt(camera.position, camera.target, camera.up);
  v.proj = glm::perspective(glm::radians(camera.fovY), float(width) / float(height), camera.znear, camera.zfar);
  v.viewProj = v.proj * v.view;
  v.invViewProj = glm::inverse(v.viewProj);
  return v;
}

} // namespace rtlab
