// Lights as the reference sees them: the GPU's irradiance model (shaders/common/lights.glsl,
// lightIrradiance: glTF units, range window, spot cone, a rectangle as a point at its centre with
// intensity radiance * area * cos) and the light's shape for visibility (docs/measuring.md
// "visibility": a cone of directions, a disk facing the point, a rectangle's area).
#pragma once
#include "scene/scene.h"

#include <glm/glm.hpp>

namespace rtlab::reference {

// Irradiance at p on a surface facing the light (no cosine at the receiver, no visibility), and
// the unit direction from p toward the light. Mirrors lightIrradiance() in lights.glsl.
glm::vec3 lightIrradiance(const Light& light, const glm::vec3& p, glm::vec3& toLight);

// Does the light have an extent (radius, angle or area > 0)? Without one, visibility is binary
// and one shadow ray decides it.
bool lightHasExtent(const Light& light);

// A shadow ray toward a point of the light's shape: the unit `direction` from p, and the ray's end
// `tfar` (infinite for a directional light), short of the light point by a relative 1e-4 so that
// geometry on which an emitter lies does not occlude it.
struct ShadowRay {
  glm::vec3 direction{0.0f};
  float tfar = 0.0f;
};
// u in [0,1)^2 picks the point: uniform over the directional light's cone of angular radius
// `angle`, over the disk of `radius` facing p (point, spot), over the rectangle (rect). A light
// without extent ignores u.
ShadowRay shadowRayToLight(const Light& light, const glm::vec3& p, glm::vec2 u);

} // namespace rtlab::reference
