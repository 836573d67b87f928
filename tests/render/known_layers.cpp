#include "known_layers.h"

#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"

#include <algorithm>
#include <cmath>

namespace rtlab {
namespace {

constexpr float kFovY = 60.0f;
constexpr float kBackdropDepth = 50.0f;

bool covers(const KnownLayer& l, const glm::vec2& ndc) {
  return ndc.x >= l.ndcMin.x && ndc.x <= l.ndcMax.x && ndc.y >= l.ndcMin.y && ndc.y <= l.ndcMax.y;
}

} // namespace

Scene makeKnownLayersScene(const std::string& name, const std::vector<KnownLayer>& layers, const glm::vec3& backdrop,
                           float aspect) {
  using namespace builtin;
  const float halfH = std::tan(glm::radians(kFovY * 0.5f)), halfW = halfH * aspect;
  auto quad = [&](const std::string& id, float z, glm::vec2 lo, glm::vec2 hi) {
    const glm::vec3 center(0.5f * (lo.x + hi.x) * halfW * z, 0.5f * (lo.y + hi.y) * halfH * z, -z);
    return makeQuad(id, center, {0.5f * (hi.x - lo.x) * halfW * z, 0, 0}, {0, 0.5f * (hi.y - lo.y) * halfH * z, 0});
  };
  auto material = [](const std::string& id, const glm::vec3& emission, float alpha, bool blend) {
    Material m = diffuseMaterial(id, glm::vec3(0.0f));
    m.emissive = emission;
    m.baseColor.w = alpha;
    m.alphaMode = blend ? AlphaMode::Blend : AlphaMode::Opaque;
    m.doubleSided = true;
    return m;
  };
  SceneBuilder b(name);
  b.addObject(quad("backdrop", kBackdropDepth, glm::vec2(-1.2f), glm::vec2(1.2f)),
              b.addMaterial(material("backdrop", backdrop, 1.0f, false)));
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const KnownLayer& l = layers[i];
    const std::string id = "layer" + std::to_string(i);
    b.addObject(quad(id, l.depth, l.ndcMin, l.ndcMax), b.addMaterial(material(id, l.emission, l.alpha, !l.opaque)));
  }
  Light light = directionalLight("off", {0, -1, -1}, 1.0f, 0.5f);
  light.intensity = 0.0f;
  b.addLight(light);
  Scene scene = b.finish(camera({0, 0, 0}, {0, 0, -1}, kFovY));
  scene.camera.znear = 0.05f;
  scene.camera.zfar = 2.0f * kBackdropDepth;
  scene.ambient = glm::vec3(0.0f);
  return scene;
}

glm::dvec3 exactOver(const std::vector<KnownLayer>& layers, const glm::vec3& backdrop, const glm::vec2& ndc) {
  float opaqueDepth = kBackdropDepth;
  glm::dvec3 c(backdrop);
  for (const KnownLayer& l : layers)
    if (l.opaque && covers(l, ndc) && l.depth < opaqueDepth) {
      opaqueDepth = l.depth;
      c = glm::dvec3(l.emission);
    }
  std::vector<const KnownLayer*> in;
  for (const KnownLayer& l : layers)
    if (!l.opaque && covers(l, ndc) && l.depth < opaqueDepth) in.push_back(&l);
  std::sort(in.begin(), in.end(), [](const KnownLayer* a, const KnownLayer* b) { return a->depth > b->depth; });
  for (const KnownLayer* l : in) c = double(l->alpha) * glm::dvec3(l->emission) + (1.0 - double(l->alpha)) * c;
  return c;
}

glm::ivec2 pixelAt(const glm::vec2& ndc, int width, int height) {
  const int x = std::clamp(int((ndc.x * 0.5f + 0.5f) * float(width)), 0, width - 1);
  const int y = std::clamp(int((ndc.y * 0.5f + 0.5f) * float(height)), 0, height - 1);
  return {x, height - 1 - y};
}

} // namespace rtlab
