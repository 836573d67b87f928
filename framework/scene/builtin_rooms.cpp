// Built-in scenes for indirect light, transparency and area lights: `cornell`, `gi_wall`, `panes`,
// `arealight`, `arealight_ramp`. Lighting targets as in builtin_shadow.cpp (key irradiance about 3).
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

// gi_wall: one bounce past a thin occluder (docs/scene-format.md). A white floor 7x6, a saturated
// red bounce wall at x = -3 facing +x, and between the wall and the receiver (the floor at x > 0) a
// white occluder wall 0.05 thick and 1.5 high at x = -0.5: thinner than one LPV cell at every grid
// (7/64 = 0.11 at 64 cells), and low enough that the upper wall's light passes over it. Light 0 is
// a spot above the gap between the two walls aimed at the red wall; its cone (45 deg) misses the
// receiver, so the receiver's light is indirect. Move it with the light0.* keys.
Scene makeGiWall() {
  SceneBuilder b("gi_wall");
  const int white = b.addMaterial(diffuseMaterial("white", glm::vec3(0.73f), 0.9f));
  const int red = b.addMaterial(diffuseMaterial("red", {0.8f, 0.05f, 0.04f}, 0.9f));
  b.addObject(makeQuad("floor", {0, 0, 0}, {3.5f, 0, 0}, {0, 0, -3.0f}, 4), white);
  b.addObject(makeQuad("bounce_wall", {-3.0f, 1.5f, 0}, {0, 0, -2.5f}, {0, 1.5f, 0}, 4), red);
  b.addObject(makeBox("occluder", {0.05f, 1.5f, 5.0f}), white, placed({-0.5f, 0.75f, 0}));
  // 45 cd at 2.75 from the wall's lit centre, at 57 deg from its normal: E about 3 there.
  b.addLight(spotLight("key", {-1.5f, 3.5f, 0}, {-3.0f, 1.2f, 0}, 45.0f, 35.0f, 45.0f, 0.1f));
  return b.finish(camera({4.5f, 4.0f, 6.0f}, {-0.8f, 0.6f, 0}, 45.0f));
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

namespace {

Light rectLight(const std::string& name, const glm::vec3& centre, const glm::vec3& emits, const glm::vec3& right,
                const glm::vec3& up, float width, float height, float nits, bool twoSided) {
  Light l;
  l.name = name;
  l.type = LightType::Rect;
  l.position = centre;
  l.direction = emits;
  l.right = right;
  l.up = up;
  l.width = width;
  l.height = height;
  l.intensity = nits;
  l.twoSided = twoSided;
  return l;
}

} // namespace

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
  b.addLight(rectLight("area", {0, 2.5f, -1.0f}, {0, -1, 0}, {1, 0, 0}, {0, 0, -1}, 2.0f, 1.0f, 10.0f, false));
  return b.finish(camera({0, 1.6f, 7.0f}, {0, 0.5f, -1.0f}, 45.0f));
}


// arealight_ramp: the extremes of an area light on one floor (docs/scene-format.md). Eleven strips
// along x with perceptual roughness 0, 0.1, ..., 1 (left to right), each split in depth: a grey
// dielectric half in front (z > -1.5) and a copper metal half behind. A low camera looks along the
// floor, so the far floor is seen at grazing angles (cos theta_v about 0.06 at its far end).
// Light 0 is a dim directional key (the shadow stage's light). Light 1: a one-sided 4 x 0.6 strip
// light 1.5 above the floor, facing down, whose reflection runs down the ramp. Light 2: a two-sided
// vertical 1.2 x 1.0 light at the back that straddles the floor's plane (y from -0.3 to 0.7), so
// the floor sees only its upper part: horizon clipping.
Scene makeAreaLightRamp() {
  SceneBuilder b("arealight_ramp");
  constexpr int kStrips = 11;
  constexpr float kStripWidth = 0.6f, kFront = 4.5f, kSplit = -1.5f, kBack = -6.0f;
  const float x0 = -0.5f * kStripWidth * kStrips;
  for (int k = 0; k < kStrips; ++k) {
    const float roughness = float(k) / float(kStrips - 1);
    const std::string id = std::to_string(k);
    Material dielectric = diffuseMaterial("dielectric_r" + id, glm::vec3(0.5f), roughness);
    Material metal = diffuseMaterial("copper_r" + id, {0.95f, 0.64f, 0.54f}, roughness);
    metal.metallic = 1.0f;
    const int dielectricMat = b.addMaterial(dielectric), metalMat = b.addMaterial(metal);
    const float cx = x0 + (float(k) + 0.5f) * kStripWidth;
    const float hx = 0.5f * kStripWidth;
    const float frontZ = 0.5f * (kFront + kSplit), frontH = 0.5f * (kFront - kSplit);
    const float backZ = 0.5f * (kSplit + kBack), backH = 0.5f * (kSplit - kBack);
    b.addObject(makeQuad("floor_dielectric_r" + id, {cx, 0, frontZ}, {hx, 0, 0}, {0, 0, -frontH}, 2), dielectricMat);
    b.addObject(makeQuad("floor_copper_r" + id, {cx, 0, backZ}, {hx, 0, 0}, {0, 0, -backH}, 2), metalMat);
  }

  b.addLight(directionalLight("key", {-0.3f, -1.0f, -0.5f}, 0.3f, 0.5f));
  b.addLight(rectLight("strip", {0, 1.5f, -1.5f}, {0, -1, 0}, {1, 0, 0}, {0, 0, -1}, 4.0f, 0.6f, 8.0f, false));
  b.addLight(rectLight("straddling", {0, 0.2f, -4.5f}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, 1.2f, 1.0f, 6.0f, true));
  return b.finish(camera({0, 0.6f, 4.5f}, {0, 0.0f, -3.0f}, 50.0f));
}

} // namespace rtlab::builtin
