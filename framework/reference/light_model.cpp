#include "reference/light_model.h"

#include "reference/sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace rtlab::reference {
namespace {

constexpr float kShortOfLight = 1.0f - 1.0e-4f;

float smoothstep(float e0, float e1, float x) {
  if (!(e1 > e0)) return x >= e1 ? 1.0f : 0.0f; // inner == outer: a hard cone edge
  const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

glm::vec3 unit(const glm::vec3& v) {
  const float l2 = glm::dot(v, v);
  return l2 > 0.0f ? v / std::sqrt(l2) : glm::vec3(0, -1, 0);
}

} // namespace

glm::vec3 lightIrradiance(const Light& light, const glm::vec3& p, glm::vec3& toLight) {
  const glm::vec3 radiant = light.color * light.intensity;
  const glm::vec3 dir = unit(light.direction);
  if (light.type == LightType::Directional) {
    toLight = -dir;
    return radiant;
  }
  const glm::vec3 d = light.position - p;
  const float dist2 = std::max(glm::dot(d, d), 1e-8f);
  toLight = d / std::sqrt(dist2);
  float attenuation = 1.0f / dist2;
  if (light.range > 0.0f) {
    const float r = std::sqrt(dist2) / light.range;
    const float window = std::clamp(1.0f - r * r * r * r, 0.0f, 1.0f);
    attenuation *= window * window;
  }
  const float cosEmit = glm::dot(-toLight, dir);
  if (light.type == LightType::Spot) {
    attenuation *= smoothstep(std::cos(light.outerConeAngle), std::cos(light.innerConeAngle), cosEmit);
  } else if (light.type == LightType::Rect) {
    const float facing = light.twoSided ? std::abs(cosEmit) : std::max(cosEmit, 0.0f);
    attenuation *= facing * light.width * light.height;
  }
  return radiant * attenuation;
}

bool lightHasExtent(const Light& light) {
  switch (light.type) {
  case LightType::Directional: return light.angle > 0.0f;
  case LightType::Point:
  case LightType::Spot: return light.radius > 0.0f;
  case LightType::Rect: return light.width > 0.0f || light.height > 0.0f;
  }
  return false;
}

ShadowRay shadowRayToLight(const Light& light, const glm::vec3& p, glm::vec2 u) {
  ShadowRay ray;
  if (light.type == LightType::Directional) {
    const glm::vec3 toLight = -unit(light.direction);
    ray.tfar = std::numeric_limits<float>::infinity();
    if (light.angle <= 0.0f) {
      ray.direction = toLight;
    } else {
      const float cosMax = std::cos(glm::radians(std::min(light.angle, 90.0f)));
      ray.direction = Frame(toLight).toWorld(squareToCone(u, cosMax));
    }
    return ray;
  }
  glm::vec3 target = light.position;
  if (light.type == LightType::Rect) {
    target += (u.x - 0.5f) * light.width * light.right + (u.y - 0.5f) * light.height * light.up;
  } else if (light.radius > 0.0f) {
    // The emitter disk faces the point: its normal is the direction from the light to p.
    const glm::vec3 axis = p - light.position;
    if (glm::dot(axis, axis) > 0.0f) {
      const glm::vec2 d = squareToDisk(u) * light.radius;
      const Frame frame(glm::normalize(axis));
      target += frame.t * d.x + frame.b * d.y;
    }
  }
  const glm::vec3 d = target - p;
  const float distance = glm::length(d);
  if (!(distance > 0.0f)) return ray; // the point is on the light: tfar 0, nothing in between
  ray.direction = d / distance;
  ray.tfar = distance * kShortOfLight;
  return ray;
}

} // namespace rtlab::reference
