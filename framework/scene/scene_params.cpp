#include "scene/scene_params.h"

#include "params/param_set.h"
#include "util/error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace rtlab {
namespace {

constexpr double kMaxCoord = 1.0e5;

// A declared default must lie in its own range, and a scene file may hold values beyond the
// nominal ranges (the loader accepts angles up to 89 degrees, any non-negative intensity, any
// coordinates): widen a range to include the scene's value rather than fail on a valid file.
ParamSpec& widenToDefault(ParamSpec& spec) {
  for (int i = 0; i < spec.components(); ++i) {
    spec.min = std::min(spec.min, spec.def.v[i]);
    spec.max = std::max(spec.max, spec.def.v[i]);
  }
  return spec;
}

std::string lightPrefix(std::size_t i) { return "light" + std::to_string(i) + "."; }

const char* lightTypeName(LightType t) {
  switch (t) {
  case LightType::Directional: return "directional";
  case LightType::Point: return "point";
  case LightType::Spot: return "spot";
  case LightType::Rect: return "rectangular";
  }
  return "?";
}

} // namespace

std::vector<ParamSpec> sceneParamSpecs(const Scene& scene) {
  std::vector<ParamSpec> specs;
  const auto add = [&](ParamSpec spec) { specs.push_back(widenToDefault(spec)); };
  const double sceneSize = std::max(1.0, double(scene.worldBounds().radius()));
  add(ParamSpec::color("scene.ambient", "Ambient", scene.ambient, 0.0, kMaxAmbient)
          .withUnit("radiance")
          .withHelp("Constant ambient radiance (linear RGB); the frame adds ambient x diffuse albedo x AO"));
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& l = scene.lights[i];
    const std::string p = lightPrefix(i);
    const std::string what = std::string(" of light ") + std::to_string(i) + " (" + lightTypeName(l.type) + ")";
    add(ParamSpec::real(p + "intensity", "Intensity", l.intensity, 0.0, 1.0e6)
                        .withUnit(l.type == LightType::Directional ? "lux" : l.type == LightType::Rect ? "nit" : "cd")
                        .withHelp("Intensity" + what + ", glTF units"));
    add(ParamSpec::color(p + "color", "Color", l.color).withHelp("Linear RGB color" + what));
    if (l.type != LightType::Directional)
      add(ParamSpec::vector3(p + "position", "Position", l.position, -kMaxCoord, kMaxCoord)
                          .withUnit("scene units").withHelp("World position" + what));
    if (l.type != LightType::Point)
      add(ParamSpec::vector3(p + "direction", "Direction", l.direction, -1.0, 1.0)
                          .withHelp("Direction the light travels" + what + " (normalized when applied; not zero)"));
    if (l.type == LightType::Point || l.type == LightType::Spot)
      add(ParamSpec::real(p + "radius", "Radius", l.radius, 0.0, std::max(double(l.radius), sceneSize))
                          .withUnit("scene units").withHelp("Radius of the emitting disk" + what + "; 0 = a point"));
    if (l.type == LightType::Directional)
      add(ParamSpec::real(p + "angle", "Angular radius", l.angle, 0.0, 45.0)
                          .withUnit("degrees").withHelp("Angular radius of the light's cone" + what + "; 0 = a direction"));
    if (l.type == LightType::Rect) {
      const double maxSize = std::max({double(l.width), double(l.height), 4.0 * sceneSize});
      add(ParamSpec::real(p + "width", "Width", l.width, 0.0, maxSize).withUnit("scene units")
                          .withHelp("Width (along its right axis)" + what));
      add(ParamSpec::real(p + "height", "Height", l.height, 0.0, maxSize).withUnit("scene units")
                          .withHelp("Height (along its up axis)" + what));
      add(ParamSpec::boolean(p + "two_sided", "Two-sided", l.twoSided)
                          .withHelp("Emits from both faces" + what + "; false = along its direction only"));
    }
  }
  const Camera& c = scene.camera;
  add(ParamSpec::vector3("camera.position", "Camera position", c.position, -kMaxCoord, kMaxCoord)
                      .withUnit("scene units").withHelp("Camera position (world)"));
  add(ParamSpec::vector3("camera.target", "Camera target", c.target, -kMaxCoord, kMaxCoord)
                      .withUnit("scene units").withHelp("Point the camera looks at (world)"));
  add(ParamSpec::real("camera.fov", "Field of view", c.fovY, 1.0, 170.0)
                      .withUnit("degrees").withHelp("Vertical field of view"));
  return specs;
}

void applySceneParams(const ParamSet& params, Scene& scene) {
  scene.ambient = params.getVec3("scene.ambient");
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    Light& l = scene.lights[i];
    const std::string p = lightPrefix(i);
    l.intensity = params.getFloat(p + "intensity");
    l.color = params.getVec3(p + "color");
    if (params.has(p + "position")) l.position = params.getVec3(p + "position");
    if (params.has(p + "direction")) {
      glm::vec3 d = params.getVec3(p + "direction");
      if (glm::length(d) < 1e-6f) usageError("'" + p + "direction' must not be zero");
      glm::vec3 n = glm::normalize(d);
      if (l.type == LightType::Rect && glm::length(n - l.direction) > 1e-6f) {
        // Keep the rectangle's frame orthonormal around the new direction.
        glm::vec3 up = std::abs(n.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        l.right = glm::normalize(glm::cross(n, up));
        l.up = glm::cross(l.right, n);
      }
      l.direction = n;
    }
    if (params.has(p + "radius")) l.radius = params.getFloat(p + "radius");
    if (params.has(p + "angle")) l.angle = params.getFloat(p + "angle");
    if (params.has(p + "width")) l.width = params.getFloat(p + "width");
    if (params.has(p + "height")) l.height = params.getFloat(p + "height");
    if (params.has(p + "two_sided")) l.twoSided = params.getBool(p + "two_sided");
  }
  Camera& c = scene.camera;
  c.position = params.getVec3("camera.position");
  c.target = params.getVec3("camera.target");
  c.fovY = params.getFloat("camera.fov");
  if (glm::length(c.target - c.position) < 1e-6f) usageError("'camera.target' must differ from 'camera.position'");
  glm::vec3 fwd = glm::normalize(c.target - c.position);
  if (std::abs(glm::dot(fwd, glm::normalize(c.up))) > 0.999f) c.up = std::abs(fwd.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, -1);
  fitClipPlanes(c, scene.worldBounds());
}

} // namespace rtlab
