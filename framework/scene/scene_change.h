// What changed in a scene, as techniques are told (docs/scene-data.md "Scene changes"): a
// technique that bakes data from the scene (a signed distance field, a voxelization, a light
// injection) rebuilds it only when the category it depends on changed.
#pragma once
#include <vector>

namespace rtlab {

struct Light; // scene/scene.h

struct SceneChange {
  // Meshes, instances or their transforms: everything in the scene's triangle data
  // (SceneGpu::triangles()). Changes only when a scene is set (Renderer::setScene).
  bool geometry = false;
  // Scene::materials or Scene::textures. Changes only when a scene is set.
  bool materials = false;
  // Any field of any entry of Scene::lights, or their number: a scene set, or a light<N>.* key
  // whose value differs from the previous frame's. scene.ambient and the camera are not lights.
  bool lights = false;

  bool any() const { return geometry || materials || lights; }
  static SceneChange everything() { return SceneChange{true, true, true}; }
  SceneChange& operator|=(const SceneChange& o) {
    geometry = geometry || o.geometry;
    materials = materials || o.materials;
    lights = lights || o.lights;
    return *this;
  }
  bool operator==(const SceneChange&) const = default;
};

// True when both lists have the same lights, every field equal (exactly: a value set again is no
// change). The definition of SceneChange::lights.
bool sameLights(const std::vector<Light>& a, const std::vector<Light>& b);

} // namespace rtlab
