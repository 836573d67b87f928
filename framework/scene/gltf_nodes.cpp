// glTF node hierarchy -> instances, camera and lights (after validateModel, which guarantees a
// forest: every index in range, one parent per node, no cycles, finite transforms).
#include "scene/gltf_internal.h"

#include "scene/mesh_builder.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab::gltf {
namespace {

glm::mat4 localMatrix(const tinygltf::Node& n) {
  if (n.matrix.size() == 16) {
    glm::mat4 m;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) m[c][r] = static_cast<float>(n.matrix[static_cast<size_t>(c * 4 + r)]);
    return m;
  }
  glm::mat4 m(1.0f);
  if (n.translation.size() == 3)
    m = glm::translate(m, glm::vec3(glm::make_vec3(n.translation.data())));
  if (n.rotation.size() == 4) {
    glm::quat q(static_cast<float>(n.rotation[3]), static_cast<float>(n.rotation[0]),
                static_cast<float>(n.rotation[1]), static_cast<float>(n.rotation[2]));
    m *= glm::mat4_cast(glm::normalize(q));
  }
  if (n.scale.size() == 3) m = glm::scale(m, glm::vec3(glm::make_vec3(n.scale.data())));
  return m;
}

bool isFinite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

glm::vec3 unitOr(const glm::vec3& v, const glm::vec3& fallback) {
  float len = glm::length(v);
  return len > 1e-20f && std::isfinite(len) ? v / len : fallback;
}

struct Placed {
  int node;
  glm::mat4 world;
};

// The world frame of a node: position, travel direction (-Z), right (+X), up (+Y), orthonormal.
struct Frame {
  glm::vec3 position, direction, right, up;
};

Frame frameOf(const glm::mat4& w) {
  Frame f;
  f.position = glm::vec3(w[3]);
  f.direction = unitOr(-glm::vec3(w[2]), glm::vec3(0, 0, -1));
  f.right = unitOr(glm::vec3(w[0]) - f.direction * glm::dot(glm::vec3(w[0]), f.direction),
                   anyPerpendicular(f.direction));
  f.up = glm::cross(-f.direction, f.right); // node +Z x +X = +Y
  return f;
}

double number(const tinygltf::Value& obj, const char* key, double fallback) {
  if (!obj.IsObject() || !obj.Has(key)) return fallback;
  const auto& v = obj.Get(key);
  return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
}

Light punctualLight(const tinygltf::Light& src, int index, const Frame& f) {
  Light l;
  l.name = src.name.empty() ? "light" + std::to_string(index) : src.name;
  l.type = src.type == "directional" ? LightType::Directional
           : src.type == "spot"      ? LightType::Spot
                                     : LightType::Point;
  if (src.color.size() == 3) l.color = glm::vec3(glm::make_vec3(src.color.data()));
  l.intensity = static_cast<float>(src.intensity);
  l.position = f.position;
  l.direction = f.direction;
  l.right = f.right;
  l.up = f.up;
  l.range = static_cast<float>(src.range);
  l.innerConeAngle = static_cast<float>(src.spot.innerConeAngle);
  l.outerConeAngle = static_cast<float>(src.spot.outerConeAngle);
  if (l.type != LightType::Directional) l.radius = static_cast<float>(number(src.extras, "radius", 0.0));
  if (l.type == LightType::Directional) l.angle = static_cast<float>(number(src.extras, "angle", 0.0));
  return l;
}

Light areaLight(const tinygltf::Node& node, int index, const Frame& f) {
  const tinygltf::Value& a = node.extras.Get("rtlab_area_light");
  Light l;
  l.name = node.name.empty() ? "area" + std::to_string(index) : node.name;
  l.type = LightType::Rect;
  l.position = f.position;
  l.direction = f.direction;
  l.right = f.right;
  l.up = f.up;
  l.width = static_cast<float>(number(a, "width", 1.0));
  l.height = static_cast<float>(number(a, "height", 1.0));
  l.intensity = static_cast<float>(number(a, "intensity", 1.0));
  l.twoSided = a.Has("two_sided") && a.Get("two_sided").Get<bool>();
  if (a.Has("color")) {
    const auto& c = a.Get("color");
    for (int k = 0; k < 3; ++k) l.color[k] = static_cast<float>(c.Get(k).GetNumberAsDouble());
  }
  return l;
}

int punctualIndex(const tinygltf::Node& node) {
  auto it = node.extensions.find("KHR_lights_punctual");
  if (it == node.extensions.end()) return -1;
  return it->second.Get("light").GetNumberAsInt(); // shape checked by validateModel
}

bool hasAreaLight(const tinygltf::Node& node) {
  return node.extras.IsObject() && node.extras.Has("rtlab_area_light");
}

int defaultSceneIndex(const tinygltf::Model& model) {
  return model.defaultScene >= 0 ? model.defaultScene : (model.scenes.empty() ? -1 : 0);
}

// The default scene's extras.ambient (docs/scene-format.md), validated by validateModel.
void readAmbient(const tinygltf::Model& model, Scene& scene) {
  const int sceneIndex = defaultSceneIndex(model);
  if (sceneIndex < 0) return;
  const tinygltf::Value& extras = model.scenes[static_cast<size_t>(sceneIndex)].extras;
  if (!extras.IsObject() || !extras.Has("ambient")) return;
  const tinygltf::Value& a = extras.Get("ambient");
  for (int k = 0; k < 3; ++k) scene.ambient[k] = static_cast<float>(a.Get(k).GetNumberAsDouble());
}

// Depth-first, pre-order, children in file order; iterative (deep hierarchies are legal).
std::vector<Placed> traverse(const tinygltf::Model& model, const std::string& file) {
  std::vector<int> roots;
  const int sceneIndex = defaultSceneIndex(model);
  if (sceneIndex >= 0) {
    roots = model.scenes[static_cast<size_t>(sceneIndex)].nodes;
  } else {
    std::vector<char> isChild(model.nodes.size(), 0);
    for (const auto& n : model.nodes)
      for (int c : n.children) isChild[static_cast<size_t>(c)] = 1;
    for (size_t i = 0; i < model.nodes.size(); ++i)
      if (!isChild[i]) roots.push_back(static_cast<int>(i));
  }
  std::vector<Placed> order, stack;
  for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, glm::mat4(1.0f)});
  while (!stack.empty()) {
    Placed p = stack.back();
    stack.pop_back();
    const tinygltf::Node& node = model.nodes[static_cast<size_t>(p.node)];
    p.world = p.world * localMatrix(node);
    if (!isFinite(p.world)) fail(file, "node " + std::to_string(p.node) + " has a non-finite world transform");
    order.push_back(p);
    for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) stack.push_back({*it, p.world});
  }
  return order;
}

} // namespace

void convertNodes(const tinygltf::Model& model, const std::vector<std::vector<int>>& meshMap,
                  Scene& scene, const std::string& file) {
  readAmbient(model, scene);
  const std::vector<Placed> order = traverse(model, file);
  for (const Placed& p : order) {
    const tinygltf::Node& node = model.nodes[static_cast<size_t>(p.node)];
    if (node.mesh < 0) continue;
    for (int m : meshMap[static_cast<size_t>(node.mesh)]) {
      Instance inst;
      inst.mesh = m;
      inst.transform = p.world;
      const int mat = scene.meshes[static_cast<size_t>(m)].material;
      inst.transparent = mat >= 0 && scene.materials[static_cast<size_t>(mat)].alphaMode == AlphaMode::Blend;
      scene.instances.push_back(inst);
    }
  }
  const Bounds bounds = scene.worldBounds();

  // Camera: the first perspective camera in traversal order.
  for (const Placed& p : order) {
    const tinygltf::Node& node = model.nodes[static_cast<size_t>(p.node)];
    if (node.camera < 0) continue;
    const tinygltf::Camera& cam = model.cameras[static_cast<size_t>(node.camera)];
    if (cam.type != "perspective") {
      warn(file, "node " + std::to_string(p.node) + " has an orthographic camera; ignored");
      continue;
    }
    const Frame f = frameOf(p.world);
    Camera c;
    c.position = f.position;
    float distance = bounds.valid() ? glm::length(bounds.center() - f.position) : 1.0f;
    c.target = f.position + f.direction * std::max(distance, 1.0f);
    c.up = f.up;
    c.fovY = glm::degrees(static_cast<float>(cam.perspective.yfov));
    scene.camera = c;
    scene.hasFileCamera = true;
    break;
  }

  // Lights: punctual lights in node order, then area lights in node order.
  for (const Placed& p : order) {
    const int l = punctualIndex(model.nodes[static_cast<size_t>(p.node)]);
    if (l >= 0)
      scene.lights.push_back(punctualLight(model.lights[static_cast<size_t>(l)], l, frameOf(p.world)));
  }
  int areaCount = 0;
  for (const Placed& p : order) {
    const tinygltf::Node& node = model.nodes[static_cast<size_t>(p.node)];
    if (hasAreaLight(node)) scene.lights.push_back(areaLight(node, areaCount++, frameOf(p.world)));
  }
  scene.hasFileLights = !scene.lights.empty();
}

} // namespace rtlab::gltf
