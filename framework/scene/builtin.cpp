// The built-in scene registry and the builder the generators share.
#include "scene/builtin.h"

#include "scene/builtin_scenes.h"
#include "util/error.h"
#include "util/suggest.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace rtlab {

const std::vector<std::string>& builtinSceneNames() {
  static const std::vector<std::string> kNames = {"contact", "stacked", "cornell", "panes",
                                                  "arealight", "glow", "layers",
                                                  "arealight_ramp", "gi_wall"};
  return kNames;
}

bool isBuiltinScene(const std::string& name) {
  const auto& names = builtinSceneNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

Scene makeBuiltinScene(const std::string& name) {
  if (name == "contact") return builtin::makeContact();
  if (name == "stacked") return builtin::makeStacked();
  if (name == "cornell") return builtin::makeCornell();
  if (name == "panes") return builtin::makePanes();
  if (name == "arealight") return builtin::makeAreaLight();
  if (name == "glow") return builtin::makeGlow();
  if (name == "layers") return builtin::makeLayers();
  if (name == "arealight_ramp") return builtin::makeAreaLightRamp();
  if (name == "gi_wall") return builtin::makeGiWall();
  std::string list;
  for (const std::string& n : builtinSceneNames()) list += (list.empty() ? "" : ", ") + n;
  usageError("unknown scene '" + name + "'" + didYouMean(name, builtinSceneNames()) + " (built-in scenes: " + list + ")");
}

namespace builtin {

SceneBuilder::SceneBuilder(const std::string& name) {
  m_scene.name = name;
  m_scene.ambient = glm::vec3(0.04f);
  m_scene.background = glm::vec3(0.0f);
}

int SceneBuilder::addMaterial(const Material& material) {
  m_scene.materials.push_back(material);
  return static_cast<int>(m_scene.materials.size()) - 1;
}

int SceneBuilder::addObject(Mesh mesh, int material, const glm::mat4& transform) {
  mesh.material = material;
  m_scene.meshes.push_back(std::move(mesh));
  Instance inst;
  inst.mesh = static_cast<int>(m_scene.meshes.size()) - 1;
  inst.transform = transform;
  inst.transparent = material >= 0 &&
                     m_scene.materials[static_cast<size_t>(material)].alphaMode == AlphaMode::Blend;
  m_scene.instances.push_back(inst);
  return static_cast<int>(m_scene.instances.size()) - 1;
}

void SceneBuilder::addLight(const Light& light) { m_scene.lights.push_back(light); }

Scene SceneBuilder::finish(const Camera& cam) {
  m_scene.camera = cam;
  m_scene.hasFileCamera = true;
  m_scene.hasFileLights = true;
  fitClipPlanes(m_scene.camera, m_scene.worldBounds());
  return std::move(m_scene);
}

Material diffuseMaterial(const std::string& name, const glm::vec3& color, float roughness) {
  Material m;
  m.name = name;
  m.baseColor = glm::vec4(color, 1.0f);
  m.metallic = 0.0f;
  m.roughness = roughness;
  return m;
}

glm::mat4 placed(const glm::vec3& position, float yawDegrees) {
  glm::mat4 t = glm::translate(glm::mat4(1.0f), position);
  return glm::rotate(t, glm::radians(yawDegrees), glm::vec3(0, 1, 0));
}

Light spotLight(const std::string& name, const glm::vec3& position, const glm::vec3& target,
                float candela, float innerDegrees, float outerDegrees, float radius) {
  Light l;
  l.name = name;
  l.type = LightType::Spot;
  l.position = position;
  l.direction = glm::normalize(target - position);
  l.intensity = candela;
  l.innerConeAngle = glm::radians(innerDegrees);
  l.outerConeAngle = glm::radians(outerDegrees);
  l.radius = radius;
  return l;
}

Light pointLight(const std::string& name, const glm::vec3& position, float candela, float radius) {
  Light l;
  l.name = name;
  l.type = LightType::Point;
  l.position = position;
  l.intensity = candela;
  l.radius = radius;
  return l;
}

Light directionalLight(const std::string& name, const glm::vec3& direction, float lux,
                       float angleDegrees) {
  Light l;
  l.name = name;
  l.type = LightType::Directional;
  l.direction = glm::normalize(direction);
  l.intensity = lux;
  l.angle = angleDegrees;
  return l;
}

Camera camera(const glm::vec3& position, const glm::vec3& target, float fovY) {
  Camera c;
  c.position = position;
  c.target = target;
  c.up = glm::vec3(0, 1, 0);
  c.fovY = fovY;
  return c;
}

} // namespace builtin
} // namespace rtlab
