// ssao against its properties and the ray-traced reference (tests/render/ao_measure.h). Views are
// set with camera.* so that the built-in scenes give the cases of issue 6: a flat floor seen at a
// grazing angle (contact's ground, looking away from its objects), a floor meeting a wall at 90
// degrees (cornell's floor and back wall, away from the blocks), and cornell as a whole. Bounds
// were measured on llvmpipe (values in the comments) and carry a margin that still fails when
// the estimator breaks.
#include "ao_measure.h"
#include "render_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace rtlab {
namespace {

using test::joined;
using test::kCreaseView;
using test::kGrazingView;
using test::measureAo;

TEST(Ssao, GrazingFloorHasNoFalseOcclusion) {
  test::expectGrazingFloorClear("ssao", {"ssao.half_resolution=false", "ssao.half_resolution=true"});
}

TEST(Ssao, CreaseDarkensTowardsTheWallAndNotBeyondTheRadius) {
  const auto m = measureAo("cornell", "ssao", kCreaseView, 128, 256);
  ASSERT_EQ(m.glErrors, 0);
  // Floor points at distance d from the wall: AO rises with d and is 1 beyond ao.radius (0.5).
  test::expectCreaseShape(m, 0.97);
  // Measured at the defaults: rmse 0.042 against 0.172 for no AO (0.25x; the classic form --
  // sphere kernel, uniform lengths, no range check -- gives 0.098, 0.57x). The residual is the blur across the
  // crease's last pixels and the height-field test; 0.4x keeps margin for a 256-spp reference
  // and fails if the crease loses its occlusion or the floor beyond the radius darkens.
  EXPECT_LT(m.metrics.rmse, 0.4 * m.noAo.rmse);
  EXPECT_EQ(m.metrics.nanCount, 0u);
}

TEST(Ssao, ErrorOnCornellDecreasesWithSampleCount) {
  // Blur off: the per-pixel estimator's variance is what the sample count buys down.
  std::vector<double> rmse;
  for (int samples : {4, 16, 64}) {
    const auto m =
        measureAo("cornell", "ssao", {"ssao.blur=false", "ssao.samples=" + std::to_string(samples)}, 96, 256);
    rmse.push_back(m.metrics.rmse);
  }
  EXPECT_LT(rmse[1], rmse[0]);
  EXPECT_LT(rmse[2], rmse[1]);
}

TEST(Ssao, DepthAwareUpsamplingBeatsNearest) {
  // Half resolution, blur off: the stage output (depth-aware upsampling of ao.raw) against the
  // ssao.raw view (the same texels, nearest-upsampled). Measured at 128x128: cornell 0.0705
  // against 0.0797, contact 0.0295 against 0.0485 -- nearest smears each texel across
  // silhouettes and creases.
  for (const char* scene : {"cornell", "contact"}) {
    const auto m = measureAo(scene, "ssao", {"ssao.half_resolution=true", "ssao.blur=false"}, 128, 256);
    TestRender r = renderTestFrame(m.frame, {"ssao.raw"});
    const Metrics nearest = computeMetrics(m.reference, r.renderer->readAov("ssao.raw"));
    std::printf("%s half resolution: depth-aware %.4f, nearest %.4f\n", scene, m.metrics.rmse, nearest.rmse);
    EXPECT_LT(m.metrics.rmse, 0.95 * nearest.rmse) << scene;
  }
}

TEST(Ssao, AoScalesOnlyAmbientLight) {
  // color(no AO) - color(ssao) = ambient * diffuse albedo * (1 - ao) on every surface pixel:
  // cornell has no metals, no material occlusion and no indirect technique, so this is the only
  // term AO may change; direct light must be untouched.
  TestFrame plain = makeTestFrame("cornell", "", {}, 64, 64);
  TestRender a = renderTestFrame(plain, {"color", "albedo"});
  const Image without = a.renderer->readAov("color");
  const Image albedo = a.renderer->readAov("albedo");
  TestFrame f = makeTestFrame("cornell", "ssao", {}, 64, 64);
  TestRender b = renderTestFrame(f, {"color", "ao"});
  const Image withAo = b.renderer->readAov("color");
  const Image ao = b.renderer->readAov("ao");
  const glm::vec3 ambient = f.scene.ambient;
  double worst = 0.0, darkened = 0.0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      if (ao.mask[std::size_t(y) * 64 + x] < 0.5f) continue;
      for (int c = 0; c < 3; ++c) {
        const double expected = ambient[c] * albedo.at(x, y, c) * (1.0 - ao.at(x, y, 0));
        const double delta = without.at(x, y, c) - withAo.at(x, y, c);
        // fp16 color: relative rounding 2^-11 of values up to about 4.
        worst = std::max(worst, std::abs(delta - expected) - 1e-3 * without.at(x, y, c));
        darkened = std::max(darkened, delta);
      }
    }
  EXPECT_LT(worst, 1e-3);
  EXPECT_GT(darkened, 0.005) << "the AO must darken the ambient term somewhere";
}

TEST(Ssao, ExtremesAreFiniteAndExcludeSky) {
  const std::vector<std::vector<std::string>> cases = {
      joined(kGrazingView, {"ao.radius=0.01"}),
      joined(kGrazingView, {"ao.radius=10"}),
      {"ao.radius=10", "ssao.half_resolution=true"},
      // The camera 0.0005 from the left wall, looking nearly along it: the wall enters the view
      // nearer than the near plane (0.01 here), which cuts it at the left edge.
      {"camera.position=-2.7495,1,1", "camera.target=-2.6,1,-2.75"},
      // The camera 0.02 above the floor, looking along it.
      {"camera.position=0,0.02,2", "camera.target=0,0.02,-2"},
  };
  test::expectExtremesFinite("ssao", cases);
}

TEST(Ssao, AoResourcesExistOnlyWhileActiveAndNeeded) {
  auto aoBytes = [](const TestRender& r) {
    std::size_t bytes = 0;
    for (const auto& res : r.renderer->resources())
      if (res.name.rfind("ao.", 0) == 0) bytes += res.bytes;
    return bytes;
  };
  TestFrame none = makeTestFrame("cornell", "none", {}, 64, 64);
  EXPECT_EQ(aoBytes(renderTestFrame(none, {"color"})), 0u);
  TestFrame on = makeTestFrame("cornell", "ssao", {}, 64, 64);
  const std::size_t fullBytes = aoBytes(renderTestFrame(on, {"color"}));
  EXPECT_GT(fullBytes, 0u);
  // Asking only for depth needs no AO: every ssao pass is culled and its textures released.
  const TestRender depth = renderTestFrame(on, {"depth"});
  EXPECT_EQ(aoBytes(depth), 0u);
  for (const auto& p : depth.renderer->lastPasses())
    EXPECT_TRUE(p.technique != "ssao" || !p.kept) << p.name;
  // Half resolution holds a quarter of the AO-resolution textures.
  TestFrame half = makeTestFrame("cornell", "ssao", {"ssao.half_resolution=true"}, 64, 64);
  EXPECT_LT(aoBytes(renderTestFrame(half, {"color"})), fullBytes / 2);
  EXPECT_EQ(aoBytes(renderTestFrame(none, {"color"})), 0u);
}

TEST(Ssao, DebugViewsRender) {
  test::expectDebugViewsRender("ssao", {});
}

} // namespace
} // namespace rtlab
