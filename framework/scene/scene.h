// The scene as the renderer and the reference see it: flattened, validated, in world space where
// it matters. Filled by the glTF loader (gltf_loader.h) or a built-in generator (builtin.h).
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace rtlab {

struct Bounds {
  glm::vec3 min{std::numeric_limits<float>::max()};
  glm::vec3 max{-std::numeric_limits<float>::max()};
  bool valid() const { return min.x <= max.x && min.y <= max.y && min.z <= max.z; }
  void extend(const glm::vec3& p) { min = glm::min(min, p); max = glm::max(max, p); }
  void extend(const Bounds& b) { if (b.valid()) { extend(b.min); extend(b.max); } }
  glm::vec3 center() const { return (min + max) * 0.5f; }
  float radius() const { return valid() ? 0.5f * glm::length(max - min) : 0.0f; }
};

struct Vertex {
  glm::vec3 position{0};
  glm::vec3 normal{0, 1, 0};
  glm::vec4 tangent{1, 0, 0, 1}; // xyz tangent, w handedness (glTF convention)
  glm::vec2 uv{0};
};

// 8-bit RGBA texel data decoded from an image file. `srgb` is true when glTF uses the texture as
// a color (base color, emissive), false for data (normal, metallic-roughness, occlusion).
struct TextureImage {
  std::string name;
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba8; // width*height*4, rows top to bottom
  bool srgb = false;
};

enum class AlphaMode { Opaque, Mask, Blend };

// glTF metallic-roughness material. Texture fields index Scene::textures; -1 = none.
struct Material {
  std::string name;
  glm::vec4 baseColor{1};
  float metallic = 0.0f;
  float roughness = 1.0f;
  glm::vec3 emissive{0};
  float normalScale = 1.0f;
  float occlusionStrength = 1.0f;
  int baseColorTexture = -1;
  int metallicRoughnessTexture = -1;
  int normalTexture = -1;
  int emissiveTexture = -1;
  int occlusionTexture = -1;
  AlphaMode alphaMode = AlphaMode::Opaque;
  float alphaCutoff = 0.5f;
  bool doubleSided = false;
};

// One glTF primitive as an indexed triangle list (non-indexed input gets 0,1,2,...). Vertices are
// in the mesh's local space; normals always present (generated when missing); tangents generated
// when the material has a normal map and the file has none.
struct Mesh {
  std::string name;
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;
  int material = -1; // index into Scene::materials; -1 = default material
  Bounds bounds;     // local-space bounds
};

// A mesh placed in the world. `transform` is the node's world matrix.
struct Instance {
  int mesh = 0;
  glm::mat4 transform{1};
  bool transparent = false; // material alphaMode == Blend
};

enum class LightType { Directional, Point, Spot, Rect };

// Lights are numbered as docs/contract.md says: KHR_lights_punctual in depth-first node order, then
// area lights from extras, then the default light when the file has none.
struct Light {
  std::string name;
  LightType type = LightType::Directional;
  glm::vec3 color{1};
  float intensity = 1.0f;        // glTF units: lux (directional), candela (point/spot), nits (rect)
  glm::vec3 position{0};         // world; unused for directional
  glm::vec3 direction{0, -1, 0}; // world, unit: the direction light travels (node -Z)
  float range = 0.0f;            // 0 = infinite
  float innerConeAngle = 0.0f;   // radians (spot)
  float outerConeAngle = 0.7853982f;
  float radius = 0.0f;           // point/spot: emitter disk radius, scene units
  float angle = 0.0f;            // directional: angular radius, degrees
  float width = 0.0f, height = 0.0f; // rect: size along `right` and `up`
  glm::vec3 right{1, 0, 0};      // rect: world axes of the rectangle; it emits along `direction`
  glm::vec3 up{0, 0, 1};
  bool twoSided = false;         // rect: emits from both faces (light<N>.two_sided), else along `direction` only
};

// Perspective camera. Aspect always comes from the frame size.
struct Camera {
  glm::vec3 position{0, 0, 5};
  glm::vec3 target{0};
  glm::vec3 up{0, 1, 0};
  float fovY = 45.0f; // vertical, degrees
  float znear = 0.05f;
  float zfar = 100.0f;
};

struct Scene {
  std::string name; // built-in name or file stem
  std::vector<Mesh> meshes;
  std::vector<Instance> instances;
  std::vector<Material> materials;
  std::vector<TextureImage> textures;
  std::vector<Light> lights;
  Camera camera;
  bool hasFileCamera = false;
  bool hasFileLights = false;
  glm::vec3 ambient{0.03f}; // constant ambient radiance (later scaled by ao, plus indirect)
  glm::vec3 background{0.0f};

  Bounds worldBounds() const; // over all instances
  bool hasTransparency() const;
  bool hasAreaLight() const;
};

// A camera framed on the bounds (used when a file has none); looks at the center from +z, slightly
// above, with the whole bounding sphere in view for the given vertical fov.
Camera frameBounds(const Bounds& bounds, float fovYDegrees = 45.0f);

// Near/far planes that enclose the scene from the camera (keeps depth precision).
void fitClipPlanes(Camera& camera, const Bounds& bounds);

// The default light for files without lights: directional, from above and to the side.
Light defaultLight(const Bounds& bounds);

} // namespace rtlab
