// Issue 12: no speckles in the umbrae of the moment-based soft shadows. On `stacked` and
// `contact` at 640x360 (defaults), the share of the reference's deep umbra (reference visibility
// exactly 0, eroded by 3 px: image/umbra_speckles.h) where a technique's visibility exceeds 0.05
// is at most 0.05% for vssm and msm, and for pcss, the control that filters the depth map itself.
// With the float summed-area table the shares were 0.5-14% (techniques/vssm/README.md and
// techniques/msm/README.md, "Speckles": the table's rounding and MSM's half-float storage).
#include "render_fixture.h"

#include "app/frame_options.h"
#include "app/reference_run.h"
#include "image/umbra_speckles.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace rtlab {
namespace {

constexpr int kWidth = 640, kHeight = 360;
// 64 stratified samples: a pixel whose light is blocked over its whole disk or cone reads exactly
// 0 for any sample count, so the umbra is exact; the 3 px erosion keeps the penumbra's darkest,
// noisy pixels (where a few samples may all be blocked) out of it.
constexpr int kSpp = 64;
constexpr double kMaxShare = 0.0005;

class UmbraSpeckleShare : public ::testing::TestWithParam<const char*> {};

TEST_P(UmbraSpeckleShare, MomentShadowsLeaveNoLitPixelsInTheUmbra) {
  const std::string scene = GetParam();
  Image reference;
  for (const char* technique : {"pcss", "vssm", "msm"}) {
    TestFrame f = makeTestFrame(scene, technique, {}, kWidth, kHeight);
    TestRender r = renderTestFrame(f, {"visibility"});
    EXPECT_EQ(r.glErrors, 0) << technique;
    const Image visibility = r.renderer->readAov("visibility"); // before the reference re-renders
    if (reference.pixels.empty()) {
      // The reference does not depend on the active technique: one per scene.
      const ResolvedFrame resolved = resolvedOf(f);
      reference = renderReferenceFrame(*r.renderer, resolved, "visibility", kSpp, false);
    }
    const UmbraSpeckles s = measureUmbraSpeckles(reference, visibility);
    std::printf("%-8s %-5s umbra %zu px, speckles %zu, share %.3f%%\n", scene.c_str(), technique, s.umbraPixels,
                s.speckles, 100.0 * s.share());
    // Measured: about 5200 deep-umbra pixels on stacked, 3000 on contact; the bound keeps the
    // test from passing on an empty umbra (0.05% is then 2.6 and 1.5 pixels).
    EXPECT_GT(s.umbraPixels, std::size_t(2000)) << technique;
    EXPECT_LE(s.share(), kMaxShare) << technique << " on " << scene;
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, UmbraSpeckleShare, ::testing::Values("stacked", "contact"));

} // namespace
} // namespace rtlab
