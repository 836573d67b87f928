// Properties of the filtered shadow techniques that need no reference: PCF of radius 0 without
// hardware comparison is shadow_map pixel for pixel; PCSS with a light of size zero and no
// minimum footprint is the hard shadow; PCSS with no blocker in the search region is fully lit;
// PCSS shadows widen as the light grows (more partially lit pixels).
#include "render_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace rtlab {
namespace {

constexpr int kSize = 96;

Image visibility(const std::string& scene, const std::string& technique, const std::vector<std::string>& sets) {
  TestFrame f = makeTestFrame(scene, technique, sets, kSize, kSize);
  TestRender r = renderTestFrame(f, {"visibility"});
  EXPECT_EQ(r.glErrors, 0);
  return r.renderer->readAov("visibility");
}

std::size_t differingPixels(const Image& a, const Image& b, float tolerance = 0.0f) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) n += std::abs(a.pixels[i] - b.pixels[i]) > tolerance ? 1 : 0;
  return n;
}

std::size_t partialPixels(const Image& v) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < v.pixels.size(); ++i)
    if (v.mask[i] > 0.5f && v.pixels[i] > 0.02f && v.pixels[i] < 0.98f) ++n;
  return n;
}

TEST(Pcf, RadiusZeroEqualsShadowMap) {
  for (const char* scene : {"contact", "stacked"}) {
    const Image hard = visibility(scene, "shadow_map", {});
    const Image pcf = visibility(scene, "pcf", {"pcf.radius=0", "pcf.hardware_2x2=false"});
    EXPECT_EQ(differingPixels(hard, pcf), 0u) << scene;
  }
}

TEST(Pcf, SingleTapEqualsShadowMap) {
  const Image hard = visibility("contact", "shadow_map", {});
  const Image pcf = visibility("contact", "pcf", {"pcf.samples=1", "pcf.pattern=poisson"});
  EXPECT_EQ(differingPixels(hard, pcf), 0u);
}

TEST(Pcf, WiderKernelSoftensEdges) {
  const Image narrow = visibility("contact", "pcf", {"pcf.radius=1"});
  const Image wide = visibility("contact", "pcf", {"pcf.radius=16"});
  EXPECT_GT(partialPixels(wide), 2 * partialPixels(narrow));
}

TEST(Pcss, ZeroSizeLightIsTheHardShadow) {
  const Image hard = visibility("contact", "shadow_map", {});
  const Image pcss = visibility("contact", "pcss", {"light0.radius=0", "pcss.min_penumbra=0"});
  EXPECT_EQ(differingPixels(hard, pcss), 0u);
  // With the default 1-texel minimum footprint the difference stays on shadow edges (measured
  // 0.40% of this 96x96 frame; the bound allows edge pixels only, not a changed shadow).
  const Image soft = visibility("contact", "pcss", {"light0.radius=0"});
  const double fraction = double(differingPixels(hard, soft, 0.01f)) / double(kSize * kSize);
  std::printf("pcss, zero-size light, 1-texel minimum footprint: %.2f%% of pixels differ from shadow_map\n",
              100.0 * fraction);
  EXPECT_LT(fraction, 0.05);
}

TEST(Pcss, LargerLightWidensPenumbrae) {
  const Image small = visibility("contact", "pcss", {"light0.radius=0.05"});
  const Image large = visibility("contact", "pcss", {"light0.radius=0.5"});
  EXPECT_GT(partialPixels(large), 2 * partialPixels(small));
}

TEST(Pcss, DirectionalLightUsesTheAngle) {
  const Image small = visibility("stacked", "pcss", {"light0.angle=0.2"});
  const Image large = visibility("stacked", "pcss", {"light0.angle=4"});
  EXPECT_GT(partialPixels(large), 2 * partialPixels(small));
}

TEST(Pcss, NoBlockerIsFullyLit) {
  // Open ground far from every object: the blocker search finds nothing, so exactly 1 (not 0/0).
  const Image v = visibility("contact", "pcss", {"light0.radius=0.5"});
  TestFrame f = makeTestFrame("contact", "pcss", {}, kSize, kSize);
  int x = 0, y = 0;
  ASSERT_TRUE(projectToPixel(f, glm::vec3(0.0f, 0.0f, 4.0f), x, y));
  EXPECT_EQ(v.at(x, y, 0), 1.0f);
}

} // namespace
} // namespace rtlab
