// The built-in `glow` scene (docs/scene-format.md "Built-in scenes") is what a bloom threshold of 1
// must sort: emitters of luma 1 to 1e4 reach the linear `color` AOV at their luma (no fp16 clamp
// below 65504), the white `snow` panel straddles luma 1, nothing else reaches luma 0.1, the small
// emitters cover the pixels their size says and the sub-pixel ones at most one pixel each.
#include <gtest/gtest.h>

#include "image/image.h"
#include "render_fixture.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace rtlab {
namespace {

constexpr int kWidth = 640, kHeight = 360;

float luma(const Image& img, int x, int y) {
  return 0.2126f * img.at(x, y, 0) + 0.7152f * img.at(x, y, 1) + 0.0722f * img.at(x, y, 2);
}

struct Glow {
  TestFrame frame;
  Image color;
};

const Glow& glow() {
  static const Glow g = [] {
    Glow out;
    out.frame = makeTestFrame("glow", "", {}, kWidth, kHeight);
    TestRender r = renderTestFrame(out.frame, {"color"});
    EXPECT_EQ(r.glErrors, 0);
    out.color = r.renderer->readAov("color");
    return out;
  }();
  return g;
}

const Mesh& mesh(const std::string& name) {
  const auto& meshes = glow().frame.scene.meshes;
  auto it = std::find_if(meshes.begin(), meshes.end(), [&](const Mesh& m) { return m.name == name; });
  if (it == meshes.end()) throw std::runtime_error("glow has no mesh " + name);
  return *it;
}

// The pixel rectangle [x0, x1] x [y0, y1] covering the projection of a mesh's bounds (all the
// emitters and the snow panel lie in z = 0 with identity transforms), grown by `margin` pixels.
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  bool contains(int x, int y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};
PixelRect projectedRect(const Mesh& m, int margin) {
  int xa = 0, ya = 0, xb = 0, yb = 0;
  EXPECT_TRUE(projectToPixel(glow().frame, m.bounds.min, xa, ya)) << m.name;
  EXPECT_TRUE(projectToPixel(glow().frame, m.bounds.max, xb, yb)) << m.name;
  return {std::min(xa, xb) - margin, std::min(ya, yb) - margin, std::max(xa, xb) + margin, std::max(ya, yb) + margin};
}

// Pixels of luma above `level` in the rectangle.
int countAbove(const PixelRect& r, float level) {
  int n = 0;
  for (int y = std::max(r.y0, 0); y <= std::min(r.y1, kHeight - 1); ++y)
    for (int x = std::max(r.x0, 0); x <= std::min(r.x1, kWidth - 1); ++x)
      n += luma(glow().color, x, y) > level ? 1 : 0;
  return n;
}

const std::vector<std::pair<std::string, float>> kGlows = {
    {"glow_1", 1.0f}, {"glow_10", 10.0f}, {"glow_100", 100.0f}, {"glow_1000", 1000.0f}, {"glow_10000", 10000.0f}};

TEST(GlowScene, EmittersReachColorAtTheirLuma) {
  // The emitters have a black base colour and the spot's cone misses them: their radiance is their
  // emission, stored in RGBA16F (relative precision 1/1024, far below 65504).
  for (const auto& [name, strength] : kGlows) {
    const PixelRect inner = projectedRect(mesh(name), -3);
    ASSERT_LT(inner.x0, inner.x1) << name;
    for (int y = inner.y0; y <= inner.y1; ++y)
      for (int x = inner.x0; x <= inner.x1; ++x)
        ASSERT_NEAR(luma(glow().color, x, y), strength, 0.01f * strength) << name << " at " << x << "," << y;
  }
}

TEST(GlowScene, SnowStraddlesLumaOne) {
  const PixelRect inner = projectedRect(mesh("snow"), -2);
  int below = 0, above = 0, total = 0;
  for (int y = inner.y0; y <= inner.y1; ++y)
    for (int x = inner.x0; x <= inner.x1; ++x) {
      const float l = luma(glow().color, x, y);
      ASSERT_GE(l, 0.8f) << x << "," << y;
      ASSERT_LE(l, 1.2f) << x << "," << y;
      below += l < 1.0f ? 1 : 0;
      above += l > 1.0f ? 1 : 0;
      ++total;
    }
  // Both sides of the threshold hold a large share of the panel (it is lit from the left).
  EXPECT_GT(below, total / 5);
  EXPECT_GT(above, total / 5);
}

TEST(GlowScene, OnlyEmittersAndSnowReachLumaPointOne) {
  std::vector<PixelRect> bright;
  for (const Mesh& m : glow().frame.scene.meshes)
    if (m.name != "floor" && m.name != "wall") bright.push_back(projectedRect(m, 1));
  int dark = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const bool inBright = std::any_of(bright.begin(), bright.end(), [&](const PixelRect& r) { return r.contains(x, y); });
      if (inBright) continue;
      ASSERT_LT(luma(glow().color, x, y), 0.1f) << x << "," << y;
      ++dark;
    }
  EXPECT_GT(dark, kWidth * kHeight * 3 / 4);
  // Above the wall is the scene's black background.
  int x = 0, y = 0;
  ASSERT_TRUE(projectToPixel(glow().frame, {0.0f, 4.8f, -2.0f}, x, y));
  EXPECT_EQ(luma(glow().color, x, y), 0.0f);
}

TEST(GlowScene, SmallEmittersCoverTheirSize) {
  // About 4, 2 and 1 pixels across: 3 to 5 pixel centres per axis for 4 px, and so on.
  const std::vector<std::pair<std::string, std::pair<int, int>>> sparks = {
      {"spark_4px", {9, 25}}, {"spark_2px", {1, 9}}, {"spark_1px", {1, 4}}};
  for (const auto& [name, range] : sparks) {
    const int n = countAbove(projectedRect(mesh(name), 2), 1.0f);
    EXPECT_GE(n, range.first) << name;
    EXPECT_LE(n, range.second) << name;
  }
}

TEST(GlowScene, SubPixelEmittersCoverAtMostOnePixelEach) {
  // 24 squares of 0.3 px, 12 px apart: each holds at most one pixel centre, and only some of them
  // hold one (the highlights alias).
  const Mesh& grid = mesh("sparkle_grid");
  ASSERT_EQ(grid.vertices.size(), 24u * 4u);
  int lit = 0;
  for (std::size_t q = 0; q < 24; ++q) {
    glm::vec3 centre(0.0f);
    for (std::size_t v = 0; v < 4; ++v) centre += grid.vertices[q * 4 + v].position * 0.25f;
    int x = 0, y = 0;
    ASSERT_TRUE(projectToPixel(glow().frame, centre, x, y));
    const int n = countAbove({x - 4, y - 4, x + 4, y + 4}, 1.0f);
    EXPECT_LE(n, 1) << "square " << q;
    lit += n;
  }
  EXPECT_GE(lit, 1);
  EXPECT_LE(lit, 12);
}

} // namespace
} // namespace rtlab
