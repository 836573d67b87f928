// Built-in scene for order-independent transparency: `layers` (docs/scene-format.md "Built-in
// scenes"). What the transparency techniques must tell apart: a stack of 24 thin layers whose
// depths run from 0.1 to 500 (so depth-based weights see their whole range), a high-alpha layer in
// front of low-alpha ones, two layers that cut through each other, HDR emissive layers, and an
// opaque sphere that hides the far part of the stack, all in front of an opaque backdrop.
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"

#include <glm/glm.hpp>

#include <cmath>
#include <string>

namespace rtlab::builtin {
namespace {

// The camera: at the origin looking along -z with a 50 degree vertical fov; at 16:9 a point at view
// depth z and normalised device coordinates (x, y) is at (x * kHalfW * z, y * kHalfH * z, -z).
constexpr float kFovY = 50.0f;
const float kHalfH = std::tan(glm::radians(kFovY * 0.5f));
const float kHalfW = kHalfH * 16.0f / 9.0f;

// A camera-facing quad at view depth z covering the NDC rectangle [x0, x1] x [y0, y1] (at 16:9).
Mesh screenQuad(const std::string& name, float z, float x0, float x1, float y0, float y1) {
  const glm::vec3 center(0.5f * (x0 + x1) * kHalfW * z, 0.5f * (y0 + y1) * kHalfH * z, -z);
  return makeQuad(name, center, {0.5f * (x1 - x0) * kHalfW * z, 0, 0}, {0, 0.5f * (y1 - y0) * kHalfH * z, 0});
}

Material layerMaterial(const std::string& name, const glm::vec3& color, float alpha, const glm::vec3& emission) {
  Material m = diffuseMaterial(name, color, 0.5f);
  m.baseColor.w = alpha;
  m.emissive = emission;
  m.alphaMode = AlphaMode::Blend;
  m.doubleSided = true;
  return m;
}

// A saturated hue for layer k of n.
glm::vec3 hue(int k, int n) {
  const float h = 6.0f * float(k) / float(n);
  const glm::vec3 c(std::abs(h - 3.0f) - 1.0f, 2.0f - std::abs(h - 2.0f), 2.0f - std::abs(h - 4.0f));
  return 0.1f + 0.8f * glm::clamp(c, 0.0f, 1.0f);
}

} // namespace

// layers (camera at the origin looking along -z, fov 50):
// - "stack_00" ... "stack_23" on the left: layer k at view depth 0.1 * 5000^(k/23) (0.1 to 500),
//   alpha 0.15, 0.25 or 0.35 in turn, covering NDC x in [-0.95 + 0.025k, 0.2] and y in
//   [-0.9, 0.9 - 0.05k], so the depth complexity grows from 1 at the top left to 24 at the bottom
//   right of the stack. Layer 14 (depth 17.7) emits (20, 9, 2), layer 8 (depth 2.6)
//   emits 4x its own hue.
// - "occluder": an opaque grey sphere of radius 1.2 at view depth 12, hiding the stack's layers
//   12-23 around NDC (-0.45, -0.45).
// - "front_high" (alpha 0.95, white) at depth 2 in front of "back_low_0..2" (alpha 0.15; red,
//   green, blue) at depths 3, 4 and 5, top right.
// - "cross_a" and "cross_b" (alpha 0.5; cyan and magenta), turned +-35 degrees about +y so that
//   they cut through each other at depth 4, bottom right.
// - "backdrop": an opaque grey wall at depth 550 filling the view.
// Light 0 is directional from behind the camera (3 lux); ambient 0.05.
Scene makeLayers() {
  SceneBuilder b("layers");
  const int backdrop = b.addMaterial(diffuseMaterial("backdrop", glm::vec3(0.5f), 0.9f));
  const int occluder = b.addMaterial(diffuseMaterial("occluder", glm::vec3(0.35f), 0.6f));
  b.addObject(screenQuad("backdrop", 550.0f, -1.1f, 1.1f, -1.1f, 1.1f), backdrop);

  constexpr int kStack = 24;
  const float alphas[3] = {0.15f, 0.25f, 0.35f};
  for (int k = 0; k < kStack; ++k) {
    const std::string name = std::string("stack_") + (k < 10 ? "0" : "") + std::to_string(k);
    const glm::vec3 color = hue(k, kStack);
    glm::vec3 emission(0.0f);
    if (k == 14) emission = glm::vec3(20.0f, 9.0f, 2.0f);
    if (k == 8) emission = 4.0f * color;
    const float z = 0.1f * std::pow(5000.0f, float(k) / float(kStack - 1));
    const int m = b.addMaterial(layerMaterial(name, color, alphas[k % 3], emission));
    b.addObject(screenQuad(name, z, -0.95f + 0.025f * float(k), 0.2f, -0.9f, 0.9f - 0.05f * float(k)), m);
  }
  b.addObject(makeSphere("occluder", 1.2f), occluder,
              placed({-0.45f * kHalfW * 12.0f, -0.45f * kHalfH * 12.0f, -12.0f}));

  const int front = b.addMaterial(layerMaterial("front_high", glm::vec3(0.95f), 0.95f, glm::vec3(0.0f)));
  b.addObject(screenQuad("front_high", 2.0f, 0.3f, 0.6f, 0.25f, 0.85f), front);
  const glm::vec3 backColors[3] = {{0.9f, 0.1f, 0.1f}, {0.1f, 0.9f, 0.1f}, {0.1f, 0.2f, 0.95f}};
  for (int i = 0; i < 3; ++i) {
    const std::string name = "back_low_" + std::to_string(i);
    const int m = b.addMaterial(layerMaterial(name, backColors[i], 0.15f, glm::vec3(0.0f)));
    const float x0 = 0.35f + 0.1f * float(i);
    b.addObject(screenQuad(name, 3.0f + float(i), x0, x0 + 0.45f, 0.1f + 0.05f * float(i), 0.95f - 0.05f * float(i)), m);
  }

  const glm::vec3 crossCenter(0.62f * kHalfW * 4.0f, -0.5f * kHalfH * 4.0f, -4.0f);
  const glm::vec3 halfU(0.55f, 0, 0), halfV(0, 0.55f, 0);
  const int cyan = b.addMaterial(layerMaterial("cross_a", {0.1f, 0.85f, 0.9f}, 0.5f, glm::vec3(0.0f)));
  const int magenta = b.addMaterial(layerMaterial("cross_b", {0.9f, 0.1f, 0.85f}, 0.5f, glm::vec3(0.0f)));
  b.addObject(makeQuad("cross_a", glm::vec3(0), halfU, halfV), cyan, placed(crossCenter, 35.0f));
  b.addObject(makeQuad("cross_b", glm::vec3(0), halfU, halfV), magenta, placed(crossCenter, -35.0f));

  b.addLight(directionalLight("key", {0.2f, -0.3f, -1.0f}, 3.0f, 0.5f));
  Scene scene = b.finish(camera({0, 0, 0}, {0, 0, -1.0f}, kFovY));
  // The clip planes are fitted to the bounds (far / near = 1e4: near about 0.09, far about 870).
  scene.ambient = glm::vec3(0.05f);
  return scene;
}

} // namespace rtlab::builtin
