// Built-in scene for bloom and tone mapping: `glow` (docs/scene-format.md "Built-in scenes").
//
// Everything a bright pass with threshold 1 (Rec. 709 luma) must tell apart: a row of emitters of
// luma 1 to 1e4, a white surface lit to luma about 1 (the near-threshold case where a hard cut pops),
// small and sub-pixel highlights (aliasing, fireflies), on a dark floor and wall with black above and
// beside them. All emitters face +z, have a black base colour (their radiance is their emission
// alone) and lie in the plane z = 0, well inside the frame at 16:9.
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"

#include <glm/glm.hpp>

#include <array>
#include <string>

namespace rtlab::builtin {
namespace {

// Rec. 709 luma, the bright pass's measure (docs/scene-format.md).
float luma(const glm::vec3& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

// An emissive material of luma `strength`: `hue` scaled to luma 1, then by the strength.
Material emitter(const std::string& name, const glm::vec3& hue, float strength) {
  Material m = diffuseMaterial(name, glm::vec3(0.0f));
  m.emissive = hue / luma(hue) * strength;
  return m;
}

} // namespace

// glow: camera at (0, 1.5, 8) looking along -z, fov 40 (one pixel at z = 0 is 0.0162 wide at
// 640x360). Emitters of luma 1, 10, 100, 1e3 and 1e4 ("glow_1" ... "glow_10000", 0.6 squares at
// y = 3.1); small emitters of luma 1e3 about 4, 2 and 1 px across ("spark_4px", "spark_2px",
// "spark_1px"); "sparkle_grid", 8x3 squares of 0.3 px, luma 1e3; a white matte "snow" panel lit by
// the spot to luma about 0.9-1.1 (brighter on the left, nearer the light); a dark "floor" and
// "wall". Light 0 is that spot; its cone (outer 16 deg) stays below the emitters.
Scene makeGlow() {
  SceneBuilder b("glow");
  const int floorMat = b.addMaterial(diffuseMaterial("floor", glm::vec3(0.08f), 0.9f));
  const int wallMat = b.addMaterial(diffuseMaterial("wall", glm::vec3(0.05f), 0.9f));
  const int snowMat = b.addMaterial(diffuseMaterial("snow", glm::vec3(0.9f), 1.0f));

  b.addObject(makePlane("floor", 14.0f, 10.0f, 4), floorMat, placed({0, 0, 2.0f}));
  b.addObject(makeQuad("wall", {0, 2.25f, -2.0f}, {5.0f, 0, 0}, {0, 2.25f, 0}, 4), wallMat);
  b.addObject(makeQuad("snow", {0, 0.7f, 0}, {1.8f, 0, 0}, {0, 0.6f, 0}, 8), snowMat);

  // The emitter row: luma 1 white, 10 warm, 100 cool, 1e3 saturated red, 1e4 white.
  struct Glow { float strength; glm::vec3 hue; };
  const std::array<Glow, 5> glows = {{{1.0f, {1.0f, 1.0f, 1.0f}},
                                      {10.0f, {1.0f, 0.75f, 0.5f}},
                                      {100.0f, {0.55f, 0.75f, 1.0f}},
                                      {1000.0f, {1.0f, 0.08f, 0.04f}},
                                      {10000.0f, {1.0f, 1.0f, 1.0f}}}};
  for (std::size_t i = 0; i < glows.size(); ++i) {
    const std::string name = "glow_" + std::to_string(static_cast<int>(glows[i].strength));
    const int mat = b.addMaterial(emitter(name, glows[i].hue, glows[i].strength));
    const float x = -3.2f + 1.6f * static_cast<float>(i);
    b.addObject(makeQuad(name, {x, 3.1f, 0}, {0.3f, 0, 0}, {0, 0.3f, 0}), mat);
  }

  // Small emitters, left of centre at y = 2.2: about 4, 2 and 1 px across at 640x360.
  const int sparkMat = b.addMaterial(emitter("spark", glm::vec3(1.0f), 1000.0f));
  constexpr float kPixel = 0.0162f; // one pixel at z = 0, 640x360
  const std::array<int, 3> sizes = {4, 2, 1};
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const float half = 0.5f * kPixel * static_cast<float>(sizes[i]);
    b.addObject(makeQuad("spark_" + std::to_string(sizes[i]) + "px", {-2.4f + 0.6f * static_cast<float>(i), 2.2f, 0},
                         {half, 0, 0}, {0, half, 0}),
                sparkMat);
  }

  // Sub-pixel emitters, right of centre: 8 columns x 3 rows of 0.3 px squares, 0.2 apart (12.3 px,
  // so their offsets within a pixel differ and only some of them cover a pixel centre).
  const int gridMat = b.addMaterial(emitter("sparkle", glm::vec3(1.0f), 1000.0f));
  const float half = 0.5f * 0.3f * kPixel;
  Mesh grid = makeQuad("sparkle_grid", {1.2f, 1.9f, 0}, {half, 0, 0}, {0, half, 0});
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 8; ++col)
      if (row + col > 0)
        appendQuad(grid, {1.2f + 0.2f * static_cast<float>(col), 1.9f + 0.2f * static_cast<float>(row), 0},
                   {half, 0, 0}, {0, half, 0});
  computeBounds(grid);
  b.addObject(std::move(grid), gridMat);

  // Light 0: a spot in front of the snow panel and left of it: the inverse-square falloff across
  // the panel (distance 8.0 to 8.6) gives it luma about 1.1 on the left and 0.9 on the right.
  b.addLight(spotLight("key", {-1.5f, 0.7f, 8.0f}, {0, 0.7f, 0}, 245.0f, 13.0f, 15.5f, 0.1f));
  return b.finish(camera({0, 1.5f, 8.0f}, {0, 1.5f, 0}, 40.0f));
}

} // namespace rtlab::builtin
