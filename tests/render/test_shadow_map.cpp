// shadow_map on the contact scene: a ground point in the floating box's shadow has visibility 0,
// an open ground point has 1. Points are chosen from the scene's geometry (light 0 through the
// floating box onto the ground; open ground whose paths to the light and camera miss every
// object's bounds), then projected to pixels.
#include "render_fixture.h"
#include "scene_geometry.h"

#include <gtest/gtest.h>

namespace rtlab {
namespace {

constexpr int kSize = 128;

struct ContactPoints {
  glm::vec3 shadowed, open;
  bool found = false;
};

ContactPoints contactPoints(const TestFrame& f) {
  ContactPoints pts;
  const Bounds ground = test::instanceBounds(f.scene, "ground");
  const Bounds floating = test::instanceBounds(f.scene, "floating");
  if (!ground.valid() || !floating.valid()) return pts;
  const float groundY = ground.max.y;
  const glm::vec3 light = f.scene.lights[0].position;
  const glm::vec3 c = floating.center();
  const float t = (light.y - groundY) / (light.y - c.y);
  pts.shadowed = light + (c - light) * t;
  // Open ground: the first grid point (scanning from near the camera) with clear paths.
  for (float z = 4.0f; z >= -4.0f && !pts.found; z -= 0.5f) {
    for (float x = -4.0f; x <= 4.0f && !pts.found; x += 0.5f) {
      const glm::vec3 p(x, groundY, z);
      if (test::segmentHitsAnyExcept(f.scene, p, light, "ground")) continue;
      if (test::segmentHitsAnyExcept(f.scene, p, f.scene.camera.position, "ground")) continue;
      int px = 0, py = 0;
      if (!projectToPixel(f, p, px, py)) continue;
      pts.open = p;
      pts.found = true;
    }
  }
  return pts;
}

TEST(ShadowMap, FloatingBoxShadowsOpenGroundIsLit) {
  TestFrame f = makeTestFrame("contact", "shadow_map", {}, kSize, kSize);
  const ContactPoints pts = contactPoints(f);
  ASSERT_TRUE(pts.found) << "contact needs 'ground' and 'floating' meshes and open lit ground";
  ASSERT_FALSE(test::segmentHitsAnyExcept(f.scene, pts.shadowed, f.scene.camera.position, "ground"))
      << "the shadowed ground point must be visible from the camera";
  TestRender r = renderTestFrame(f, {"visibility"});
  EXPECT_EQ(r.glErrors, 0);
  const Image vis = r.renderer->readAov("visibility");
  int sx = 0, sy = 0, ox = 0, oy = 0;
  ASSERT_TRUE(projectToPixel(f, pts.shadowed, sx, sy));
  ASSERT_TRUE(projectToPixel(f, pts.open, ox, oy));
  EXPECT_EQ(vis.mask[std::size_t(sy) * kSize + sx], 1.0f);
  EXPECT_EQ(vis.at(sx, sy, 0), 0.0f) << "ground under the floating box at pixel " << sx << "," << sy;
  EXPECT_EQ(vis.at(ox, oy, 0), 1.0f) << "open ground at pixel " << ox << "," << oy;
}

TEST(ShadowMap, ShadowedPixelIsDarkerInColor) {
  TestFrame f = makeTestFrame("contact", "shadow_map", {}, kSize, kSize);
  const ContactPoints pts = contactPoints(f);
  ASSERT_TRUE(pts.found);
  TestRender shadowed = renderTestFrame(f, {"color"});
  const Image with = shadowed.renderer->readAov("color");
  TestFrame plain = makeTestFrame("contact", "", {}, kSize, kSize);
  TestRender unshadowed = renderTestFrame(plain, {"color"});
  const Image without = unshadowed.renderer->readAov("color");
  int sx = 0, sy = 0;
  ASSERT_TRUE(projectToPixel(f, pts.shadowed, sx, sy));
  // Only light 0 is shadowed: the pixel keeps the fill light and ambient, so it is darker, not black.
  EXPECT_LT(with.at(sx, sy, 0), 0.5f * without.at(sx, sy, 0));
  EXPECT_GT(with.at(sx, sy, 0), 0.0f);
}

TEST(Frame, NoneHasNoShadowPassAndFewerBytes) {
  TestFrame none = makeTestFrame("contact", "none", {}, kSize, kSize);
  TestRender a = renderTestFrame(none, {"color"});
  std::size_t bytesNone = a.stats.resourceBytes();
  for (const auto& p : a.stats.passes()) {
    EXPECT_EQ(p.name.find("shadow"), std::string::npos) << p.name;
    EXPECT_TRUE(p.technique.empty()) << p.name;
  }
  TestFrame sm = makeTestFrame("contact", "shadow_map", {}, kSize, kSize);
  TestRender b = renderTestFrame(sm, {"color"});
  bool hasDepth = false;
  for (const auto& p : b.stats.passes()) hasDepth = hasDepth || p.name == "shadow.depth";
  EXPECT_TRUE(hasDepth);
  EXPECT_LT(bytesNone, b.stats.resourceBytes());
  // Turning it off again releases its memory at the next frame.
  TestRender c = renderTestFrame(none, {"color"});
  EXPECT_EQ(c.stats.resourceBytes(), bytesNone);
}

TEST(Frame, DataAovsAreCulledToWhatTheyNeed) {
  // Asking only for depth needs the G-buffer, not the shadow map, lighting or tone mapping.
  TestFrame f = makeTestFrame("contact", "shadow_map", {}, 64, 64);
  TestRender r = renderTestFrame(f, {"depth"});
  for (const auto& p : r.renderer->lastPasses()) {
    const bool expected = p.name == "gbuffer" || p.name == "aov.depth";
    EXPECT_EQ(p.kept, expected) << p.name;
  }
  const Image depth = r.renderer->readAov("depth");
  const float near = f.scene.camera.znear, far = f.scene.camera.zfar;
  for (std::size_t i = 0; i < depth.pixelCount(); ++i) {
    if (depth.mask[i] > 0.5f) {
      EXPECT_GT(depth.pixels[i], near);
      EXPECT_LT(depth.pixels[i], far);
    } else {
      EXPECT_EQ(depth.pixels[i], 0.0f);
    }
  }
}

TEST(ShadowMap, PointLightUsesCubeMapAndShadows) {
  // A point light at light 0's position: the same floating-box shadow through a cube map.
  TestFrame f = makeTestFrame("contact", "shadow_map", {}, kSize, kSize);
  ContactPoints pts = contactPoints(f);
  ASSERT_TRUE(pts.found);
  f.scene.lights[0].type = LightType::Point;
  f.scene.name = "contact-point-light"; // its own shared renderer, so the changed light is uploaded
  TestRender r = renderTestFrame(f, {"visibility"});
  bool cube = false;
  for (const auto& res : r.renderer->resources())
    if (res.name == "shadow.depth") cube = res.bytes == std::size_t(6) * 2048 * 2048 * 4;
  EXPECT_TRUE(cube) << "a point light's map is a cube of six 2048^2 24-bit faces";
  const Image vis = r.renderer->readAov("visibility");
  int sx = 0, sy = 0, ox = 0, oy = 0;
  ASSERT_TRUE(projectToPixel(f, pts.shadowed, sx, sy));
  ASSERT_TRUE(projectToPixel(f, pts.open, ox, oy));
  EXPECT_EQ(vis.at(sx, sy, 0), 0.0f);
  EXPECT_EQ(vis.at(ox, oy, 0), 1.0f);
}

} // namespace
} // namespace rtlab
