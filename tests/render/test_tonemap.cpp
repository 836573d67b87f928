// The tone-mapping pass (shaders/shading/tonemap.frag, `tonemap.operator`): `clamp` is exposure then
// a clip to [0,1], and every operator stays finite and at most 1 at the largest input the frame can
// hold (65504, the HDR clamp) times the largest exposure (100), where a 16-bit evaluation of the
// ACES fit would overflow.
#include <gtest/gtest.h>

#include "image/image.h"
#include "render_fixture.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace rtlab {
namespace {

constexpr int kWidth = 320, kHeight = 180;

struct Pair {
  Image linear, display;
};

// The `color` AOV and the tone-mapped display colour of one frame of `glow`.
Pair render(const TestFrame& f) {
  TestRender r = renderTestFrame(f, {"color"}, true);
  EXPECT_EQ(r.glErrors, 0);
  return {r.renderer->readAov("color"), r.renderer->readDisplayColor()};
}

TEST(Tonemap, ClampIsExposureThenClip) {
  // The emitters are clipped at both exposures; the snow panel (luma 0.88-1.10) passes through at 0.8
  // and straddles 1 at exposure 1.
  for (const char* exposure : {"0.8", "1"}) {
    SCOPED_TRACE(exposure);
    const TestFrame f = makeTestFrame("glow", "", {"tonemap.operator=clamp", std::string("tonemap.exposure=") + exposure},
                                      kWidth, kHeight);
    const float e = std::stof(exposure);
    const Pair p = render(f);
    int clipped = 0, passed = 0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x)
        for (int c = 0; c < 3; ++c) {
          const float expected = std::min(p.linear.at(x, y, c) * e, 1.0f);
          // Both images are stored in 16-bit floats: 2^-10 relative.
          ASSERT_NEAR(p.display.at(x, y, c), expected, 2e-3f * std::max(expected, 0.01f)) << x << "," << y << " c" << c;
          clipped += p.linear.at(x, y, c) * e > 1.0f ? 1 : 0;
          passed += p.linear.at(x, y, c) * e > 0.5f && p.linear.at(x, y, c) * e < 1.0f ? 1 : 0;
        }
    EXPECT_GT(clipped, 100);
    EXPECT_GT(passed, 100);
  }
}

TEST(Tonemap, OperatorsStayFiniteAtMostOneAtTheLargestInput) {
  // The brightest emitter at 1e6: stored as 65504 (the HDR clamp), times exposure 100.
  for (const char* op : {"aces", "reinhard", "clamp"}) {
    SCOPED_TRACE(op);
    TestFrame f = makeTestFrame("glow", "", {std::string("tonemap.operator=") + op, "tonemap.exposure=100"}, kWidth, kHeight);
    f.scene.name = "glow_1e6";
    for (Material& m : f.scene.materials)
      if (m.name == "glow_10000") m.emissive = glm::vec3(1e6f);
    const Pair p = render(f);
    int x = 0, y = 0;
    ASSERT_TRUE(projectToPixel(f, {3.2f, 3.1f, 0.0f}, x, y)); // glow_10000's centre
    EXPECT_EQ(p.linear.at(x, y, 0), 65504.0f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(p.display.at(x, y, c), 1.0f, 1e-3f);
    for (float v : p.display.pixels) {
      ASSERT_TRUE(std::isfinite(v));
      ASSERT_GE(v, 0.0f);
      ASSERT_LE(v, 1.0f);
    }
  }
}

} // namespace
} // namespace rtlab
