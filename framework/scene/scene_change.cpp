#include "scene/scene_change.h"

#include "scene/scene.h"

#include <algorithm>

namespace rtlab {
namespace {

// A field added to Light must be compared here too: this size check fails until it is.
constexpr std::size_t kLightFields =
    sizeof(std::string) + sizeof(LightType) + 8 * sizeof(float) + 5 * sizeof(glm::vec3) + sizeof(bool);
static_assert(sizeof(Light) == (kLightFields + alignof(Light) - 1) / alignof(Light) * alignof(Light),
              "Light changed: update sameLight");

bool sameLight(const Light& a, const Light& b) {
  return a.name == b.name && a.type == b.type && a.color == b.color && a.intensity == b.intensity &&
         a.position == b.position && a.direction == b.direction && a.range == b.range &&
         a.innerConeAngle == b.innerConeAngle && a.outerConeAngle == b.outerConeAngle && a.radius == b.radius &&
         a.angle == b.angle && a.width == b.width && a.height == b.height && a.right == b.right && a.up == b.up &&
         a.twoSided == b.twoSided;
}

} // namespace

bool sameLights(const std::vector<Light>& a, const std::vector<Light>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), sameLight);
}

} // namespace rtlab
