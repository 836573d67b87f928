// Built-in scenes for the shadow stage: `contact` (contact shadows, a thin wall, a floating box)
// and `stacked` (two occluders at different heights under a directional light of finite size).
//
// Lighting targets: the key light gives a white diffuse surface an irradiance of about 3
// (radiance albedo * E / pi ~ 0.8 before tone mapping, exposure 1 + ACES).
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"

namespace rtlab::builtin {

// contact: a 12x12 ground at y = 0 with a box and a sphere resting on it, a thin wall standing on
// it, and a box floating 1.2 above it. Light 0 is a small spot light above, right and in front of
// the objects; the floating box's shadow lands on open ground behind it, at about
// x in [-0.1, 1.3], z in [-3.8, -1.8], seen under the box by the camera.
Scene makeContact() {
  SceneBuilder b("contact");
  const int ground = b.addMaterial(diffuseMaterial("ground", glm::vec3(0.8f)));
  const int boxMat = b.addMaterial(diffuseMaterial("box", {0.85f, 0.45f, 0.2f}));
  const int sphereMat = b.addMaterial(diffuseMaterial("sphere", {0.3f, 0.5f, 0.85f}, 0.4f));
  const int wallMat = b.addMaterial(diffuseMaterial("wall", {0.75f, 0.75f, 0.7f}));
  const int floatMat = b.addMaterial(diffuseMaterial("floating", {0.35f, 0.7f, 0.4f}));

  b.addObject(makePlane("ground", 12.0f, 12.0f, 8), ground);
  b.addObject(makeBox("box", glm::vec3(1.0f)), boxMat, placed({-1.2f, 0.5f, 0.8f}, 25.0f));
  b.addObject(makeSphere("sphere", 0.6f), sphereMat, placed({0.9f, 0.6f, 1.3f}));
  // Thin (0.08) wall on the left, running along z; its shadow falls to its left (-x).
  b.addObject(makeBox("wall", {0.08f, 1.5f, 2.5f}), wallMat, placed({-3.0f, 0.75f, -0.75f}));
  // Floating box: 0.8 wide, bottom at y = 1.2.
  b.addObject(makeBox("floating", glm::vec3(0.8f)), floatMat, placed({1.2f, 1.6f, -1.2f}));

  // Light 0 (shadowed key): E = 270 * cos(35.5 deg) / 74 ~ 3 at the origin. The outer cone (50
  // deg) covers all visible ground (at most 46 deg off the axis).
  b.addLight(spotLight("key", {3.0f, 7.0f, 4.0f}, {0.0f, 0.0f, 0.0f}, 270.0f, 40.0f, 50.0f, 0.1f));
  // Light 1 (unshadowed fill): about 0.15 lux at the origin.
  b.addLight(pointLight("fill", {-5.0f, 4.0f, 6.0f}, 12.0f, 0.0f));
  return b.finish(camera({0.0f, 4.5f, 9.0f}, {0.0f, 0.5f, 0.0f}, 45.0f));
}

// stacked: two thin plates at heights 0.8 and 2.2 over a ground, offset so that their shadows
// overlap partly, and a sphere half under the upper plate as a curved receiver. Light 0 is
// directional with an angular radius of 1.5 degrees, so the penumbra widens with the distance
// between occluder and receiver (about 0.08 per unit of height).
Scene makeStacked() {
  SceneBuilder b("stacked");
  const int ground = b.addMaterial(diffuseMaterial("ground", glm::vec3(0.8f)));
  const int lowMat = b.addMaterial(diffuseMaterial("plate_low", {0.85f, 0.35f, 0.3f}));
  const int highMat = b.addMaterial(diffuseMaterial("plate_high", {0.3f, 0.45f, 0.85f}));
  const int sphereMat = b.addMaterial(diffuseMaterial("sphere", glm::vec3(0.75f), 0.6f));

  b.addObject(makePlane("ground", 12.0f, 12.0f, 8), ground);
  b.addObject(makeBox("plate_low", {1.4f, 0.05f, 1.4f}), lowMat, placed({-0.4f, 0.8f, 0.3f}));
  b.addObject(makeBox("plate_high", {2.0f, 0.05f, 1.6f}), highMat, placed({0.5f, 2.2f, -0.4f}));
  b.addObject(makeSphere("sphere", 0.45f), sphereMat, placed({1.6f, 0.45f, -0.2f}));

  // Light 0: the light travels down and slightly towards +x, +z; E = 3 * cos(14 deg) ~ 2.9.
  b.addLight(directionalLight("key", {0.2f, -1.0f, 0.15f}, 3.0f, 1.5f));
  return b.finish(camera({0.0f, 5.5f, 7.5f}, {0.3f, 0.6f, 0.1f}, 45.0f));
}

} // namespace rtlab::builtin
