// Built-in scenes for indirect light, transparency and area lights: `cornell`, `panes`,
// `arealight`. Lighting targets as in builtin_shadow.cpp (key irradiance about 3).
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"

namespace rtlab::builtin {

// cornell: a 5.5 box (x, z in [-2.75, 2.75], y in [0, 5.5]) open towards +z, walls facing inward:
// white floor, ceiling and back, red left (-x) and green right (+x) walls, a tall and a short
// block. Light 0 is a spot just below the ceiling centre pointing down; the emissive
// "light_panel" above it is for looks only (it is not in the light list).
Scene makeCornell() {
  constexpr float kSize = 5.5f, h = kSize * 0.5f;
  SceneBuilder b("cornell");
  const int white = b.addMaterial(diffuseMaterial("white", glm::vec3(0.73f), 0.9f));
  const int red = b.addMaterial(diffuseMaterial("red", {0.63f, 0.065f, 0.05f}, 0.9f));
  const int green = b.addMaterial(diffuseMaterial("green", {0.14f, 0.45f, 0.091f}, 0.9f));
  Material panel = diffuseMaterial("light_panel", glm::vec3(0.78f));
  panel.emissive = glm::vec3(12.0f, 10.0f, 8.0f);
  const int panelMat = b.addMaterial(panel);

  b.addObject(makeQuad("floor", {0, 0, 0}, {h, 0, 0}, {0, 0, -h}, 4), white);
  b.addObject(makeQuad("ceiling", {0, kSize, 0}, {h, 0, 0}, {0, 0, h}, 4), white);
  b.addObject(makeQuad("back", {0, h, -h}, {h, 0, 0}, {0, h, 0}, 4), white);
  b.addObject(makeQuad("left", {-h, h, 0}, {0, 0, -h}, {0, h, 0}, 4), red);
  b.addObject(makeQuad("right", {h, h, 0}, {0, 0, h}, {0, h, 0}, 4), green);
  b.addObject(makeBox("tall_block", {1.65f, 3.3f, 1.65f}), white, placed({-1.05f, 1.65f, -0.95f}, 17.0f));
  b.addObject(makeBox("short_block", glm::vec3(1.65f)), white, placed({1.05f, 0.825f, 0.8f}, -17.0f));
  b.addObject(makeQuad("light_panel", {0, kSize - 0.01f, 0}, {0.65f, 0, 0}, {0, 0, 0.525f}), panelMat);

  // Light 0: 80 cd at 5.1 above the floor gives E ~ 3 below it. It hangs 0.4 below the ceiling so
  // that its emitter disk (radius 0.3) never pokes through the panel or the ceiling.
  b.addLight(spotLight("key", {0, 5.1f, 0}, {0, 0, 0}, 80.0f, 60.0f, 75.0f, 0.3f));
  Scene scene = b.finish(camera({0, h, 10.5f}, {0, h, 0}, 40.0f));
  // The AO showcase (ssao, hbao): an ambient strong enough that AO shows in `color`. With 0.03
  // toggling ssao changed the linear frame by at most 0.011; with 0.2 by 0.072 at 640x360
  // (docs/scene-format.md "Built-in scenes"), while the key light still dominates the lit floor.
  scene.ambient = glm::vec3(0.2f);
  return scene;
}

// panes: four coloured transparent panes (alpha 0.4-0.5; red, green and blue parallel at
// different depths, a yellow one turned 60 degrees cutting through the green one) in front of an
// opaque backdrop wall, a ground and an opaque box. Light 0 is directional.
Scene makePanes() {
  SceneBuilder b("panes");
  const int ground = b.addMaterial(diffuseMaterial("ground", glm::vec3(0.7f)));
  const int backdrop = b.addMaterial(diffuseMaterial("backdrop", {0.8f, 0.78f, 0.72f}));
  const int boxMat = b.addMaterial(diffuseMaterial("box", {0.6f, 0.6f, 0.65f}, 0.5f));
  auto pane = [&](const std::string& name, const glm::vec3& color, float alpha) {
    Material m = diffuseMaterial(name, color, 0.3f);
    m.baseColor.w = alpha;
    m.alphaMode = AlphaMode::Blend;
    m.doubleSided = true;
    return b.addMaterial(m);
  };
  const int red = pane("pane_red", {0.9f, 0.12f, 0.1f}, 0.5f);
  const int green = pane("pane_green", {0.15f, 0.85f, 0.2f}, 0.5f);
  const int blue = pane("pane_blue", {0.15f, 0.3f, 0.95f}, 0.5f);
  const int yellow = pane("pane_yellow", {0.95f, 0.85f, 0.1f}, 0.4f);

  b.addObject(makePlane("ground", 10.0f, 8.0f, 4), ground, placed({0, 0, 1.0f}));
  b.addObject(makeQuad("backdrop", {0, 3.0f, -3.0f}, {5.0f, 0, 0}, {0, 3.0f, 0}, 4), backdrop);
  b.addObject(makeBox("box", glm::vec3(0.8f)), boxMat, placed({1.6f, 0.4f, -2.0f}, 20.0f));
  const glm::vec3 halfU(1.0f, 0, 0), halfV(0, 1.0f, 0);
  b.addObject(makeQuad("pane_red", glm::vec3(0), halfU, halfV), red, placed({-0.7f, 1.5f, 0.8f}));
  b.addObject(makeQuad("pane_green", glm::vec3(0), halfU, halfV), green, placed({0.0f, 1.3f, -0.3f}));
  b.addObject(makeQuad("pane_blue", glm::vec3(0), halfU, halfV), blue, placed({0.7f, 1.7f, -1.4f}));
  b.addObject(makeQuad("pane_yellow", glm::vec3(0), {0.8f, 0, 0}, {0, 0.6f, 0}), yellow,
              placed({0.4f, 1.0f, -0.3f}, 60.0f));

  b.addLight(directionalLight("key", {-0.3f, -1.0f, -0.6f}, 3.0f, 0.5f));
  return b.finish(camera({0, 2.0f, 6.5f}, {0, 1.3f, -0.5f}, 45.0f));
}

// arealight: a glossy dielectric floor (roughness 0.2) with a sphere and a box under a 2x1
// rectangular light 2.5 above the floor, facing down. Light 0 is a dimmer shadowed spot (the
// shadow stage handles directional, spot and point lights only); light 1 is the rectangle, whose
// reflection in the floor is in view of the low camera.
Scene makeAreaLight() {
  SceneBuilder b("arealight");
  Material floor = diffuseMaterial("floor", glm::vec3(0.5f), 0.2f);
  const int floorMat = b.addMaterial(floor);
  const int sphereMat = b.addMaterial(diffuseMaterial("sphere", glm::vec3(0.8f), 0.5f));
  const int boxMat = b.addMaterial(diffuseMaterial("box", {0.7f, 0.7f, 0.75f}, 0.35f));

  b.addObject(makePlane("floor", 10.0f, 10.0f, 4), floorMat);
  b.addObject(makeSphere("sphere", 0.6f), sphereMat, placed({-1.3f, 0.6f, 0.2f}));
  b.addObject(makeBox("box", glm::vec3(0.9f)), boxMat, placed({1.4f, 0.45f, -0.3f}, 30.0f));

  // Light 0: E = 100 * cos(31 deg) / 71 ~ 1.2 at the aim point.
  b.addLight(spotLight("key", {-2.5f, 6.0f, 4.0f}, {0, 0, -0.5f}, 100.0f, 35.0f, 45.0f, 0.1f));
  // Light 1: 10 nits over 2 m^2 at 2.5 gives E ~ 3 below its centre.
  Light rect;
  rect.name = "area";
  rect.type = LightType::Rect;
  rect.position = glm::vec3(0, 2.5f, -1.0f);
  rect.direction = glm::vec3(0, -1, 0);
  rect.right = glm::vec3(1, 0, 0);
  rect.up = glm::vec3(0, 0, -1);
  rect.width = 2.0f;
  rect.height = 1.0f;
  rect.intensity = 10.0f;
  b.addLight(rect);
  return b.finish(camera({0, 1.6f, 7.0f}, {0, 0.5f, -1.0f}, 45.0f));
}

} // namespace rtlab::builtin
