// Light-space projection of light 0 for the shadow stage, fitted to the scene bounds:
// orthographic for directional lights, one perspective map for spot lights whose cone fits in
// 120 degrees, a cube map (six 90-degree faces) for point lights and wider spots.
#pragma once
#include "scene/scene.h"

#include <glm/glm.hpp>

namespace rtlab {

enum class LightProjection { Orthographic = 0, Perspective = 1, Cube = 2 };

struct LightSpace {
  LightProjection projection = LightProjection::Orthographic;
  glm::mat4 viewProj[6];  // [0] only, unless Cube (faces +X -X +Y -Y +Z -Z)
  glm::vec3 position{0};  // perspective and cube
  glm::vec3 direction{0, -1, 0};
  float znear = 0.1f, zfar = 100.0f;
  // World size of one map texel: constant for orthographic; for perspective and cube it is
  // texelScale * (distance along the light's axis).
  float texelScale = 0.0f;
  int faces() const { return projection == LightProjection::Cube ? 6 : 1; }
};

// Throws Error(Usage) for a rectangular light 0 (not supported by shadow maps).
LightSpace computeLightSpace(const Light& light, const Bounds& sceneBounds, int resolution);

} // namespace rtlab
