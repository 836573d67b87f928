// Properties of the filtered shadow techniques that need no reference: PCF of radius 0 without
// hardware comparison is shadow_map pixel for pixel; PCSS with a light of size zero and no
// minimum footprint is the hard shadow; PCSS with no blocker in the search region is fully lit;
// PCSS shadows widen as the light grows (more partially lit pixels).
#include "render_fixture.h"

#include "util/error.h"

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

namespace rtlab {
namespace {

// Soft techniques (PCSS, VSSM, MSM) share two properties: a larger light widens penumbrae, and
// penumbrae widen as the blocker rises above the receiver (contact hardening).
class SoftShadow : public ::testing::TestWithParam<std::string> {};

TEST_P(SoftShadow, LargerLightWidensPenumbrae) {
  const Image small = visibility("contact", GetParam(), {"light0.radius=0.05"});
  const Image large = visibility("contact", GetParam(), {"light0.radius=0.5"});
  EXPECT_GT(partialPixels(large), partialPixels(small) + partialPixels(small) / 2);
}

TEST_P(SoftShadow, PenumbraWidensAsTheBlockerRises) {
  // The floating box alone over open ground, at two heights; everything else is removed so only
  // its shadow is counted.
  auto frameAt = [&](float lift) {
    TestFrame f = makeTestFrame("contact", GetParam(), {"light0.radius=0.3"}, kSize, kSize);
    std::vector<Instance> kept;
    for (const auto& inst : f.scene.instances) {
      const std::string& name = f.scene.meshes[std::size_t(inst.mesh)].name;
      if (name == "ground" || name == "floating") kept.push_back(inst);
      if (name == "floating") kept.back().transform[3].y += lift;
    }
    f.scene.instances = kept;
    f.scene.name = "contact-floating-" + std::to_string(lift); // own renderer: the geometry differs
    return f;
  };
  TestFrame low = frameAt(-0.9f), high = frameAt(0.8f);
  TestRender a = renderTestFrame(low, {"visibility"});
  const std::size_t lowPartial = partialPixels(a.renderer->readAov("visibility"));
  TestRender b = renderTestFrame(high, {"visibility"});
  const std::size_t highPartial = partialPixels(b.renderer->readAov("visibility"));
  EXPECT_GT(highPartial, lowPartial + lowPartial / 4) << "low " << lowPartial << ", high " << highPartial;
}

INSTANTIATE_TEST_SUITE_P(Techniques, SoftShadow, ::testing::Values("pcss", "vssm", "msm"));

TEST(MomentShadows, PointLightIsRefusedWithAUsageError) {
  TestFrame f = makeTestFrame("contact", "vssm", {}, 32, 32);
  f.scene.lights[0].type = LightType::Point;
  f.scene.name = "contact-point-vssm";
  try {
    renderTestFrame(f, {"visibility"});
    FAIL() << "expected a usage error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::Usage);
    EXPECT_NE(std::string(e.what()).find("vssm"), std::string::npos);
  }
}

// The moment map's summed-area table is built by two compute passes of the frame graph
// (techniques/common/shadow/moment_map.cpp): row scans into "<id>.sat" as a storage image, then
// column scans in place, and the graph, not the passes, issues the barriers: image access before
// the column scans (they load what the row scans stored), texture fetch before the visibility pass
// (it samples the table), and none before the row scans (the moments are an attachment).
TEST(MomentShadows, SummedAreaTableIsBuiltByComputePassesWithPlannedBarriers) {
  for (const char* technique : {"vssm", "msm"}) {
    const std::string id = technique;
    TestFrame f = makeTestFrame("contact", id, {}, 32, 32);
    TestRender r = renderTestFrame(f, {"visibility"});
    EXPECT_EQ(r.glErrors, 0) << id;
    const std::vector<Renderer::PassInfo>& passes = r.renderer->lastPasses();
    auto find = [&](const std::string& name) {
      for (std::size_t i = 0; i < passes.size(); ++i)
        if (passes[i].name == name) return i;
      ADD_FAILURE() << id << ": no pass " << name;
      return passes.size();
    };
    const std::size_t rows = find(id + ".sat.rows"), columns = find(id + ".sat.columns"),
                      visibility = find(id + ".visibility");
    if (rows == passes.size() || columns == passes.size() || visibility == passes.size()) continue;
    EXPECT_LT(rows, columns) << id;
    EXPECT_LT(columns, visibility) << id;
    for (std::size_t i : {rows, columns}) {
      EXPECT_TRUE(passes[i].kept) << passes[i].name;
      EXPECT_TRUE(passes[i].compute) << passes[i].name;
    }
    EXPECT_EQ(passes[rows].barrier, 0u) << id;
    EXPECT_EQ(passes[columns].barrier, GLbitfield(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT)) << id;
    EXPECT_EQ(passes[visibility].barrier, GLbitfield(GL_TEXTURE_FETCH_BARRIER_BIT)) << id;
  }
}

} // namespace
} // namespace rtlab
