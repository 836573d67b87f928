// Internal to the built-in scenes: a small builder and one generator per scene.
#pragma once
#include "scene/scene.h"

#include <string>

namespace rtlab::builtin {

// Accumulates meshes, materials, instances and lights into a Scene.
class SceneBuilder {
public:
  explicit SceneBuilder(const std::string& name);

  int addMaterial(const Material& material);
  // Adds the mesh with the given material and one instance of it; returns the instance index.
  // The instance is transparent when the material's alphaMode is Blend.
  int addObject(Mesh mesh, int material, const glm::mat4& transform = glm::mat4(1.0f));
  void addLight(const Light& light);
  // Sets the camera, marks camera and lights as the scene's own, fits the clip planes.
  Scene finish(const Camera& camera);

private:
  Scene m_scene;
};

Material diffuseMaterial(const std::string& name, const glm::vec3& color, float roughness = 0.8f);
// Translation followed by a rotation of `yawDegrees` about +y.
glm::mat4 placed(const glm::vec3& position, float yawDegrees = 0.0f);
Light spotLight(const std::string& name, const glm::vec3& position, const glm::vec3& target,
                float candela, float innerDegrees, float outerDegrees, float radius);
Light pointLight(const std::string& name, const glm::vec3& position, float candela, float radius);
Light directionalLight(const std::string& name, const glm::vec3& direction, float lux,
                       float angleDegrees);
Camera camera(const glm::vec3& position, const glm::vec3& target, float fovY);

Scene makeContact();
Scene makeStacked();
Scene makeCornell();
Scene makeGiWall();
Scene makePanes();
Scene makeAreaLight();
Scene makeAreaLightRamp();
Scene makeLayers();
Scene makeGlow();

} // namespace rtlab::builtin
