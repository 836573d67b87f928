// The viewer's live figure on a real frame (framework/reference/live_metrics.h): a technique's
// AOV measured against the progressive reference once it is ready gives nearly the RMSE that
// `rtlab reference --spp 256` + `rtlab compare` give for the same frame, which is what issue 5's
// compare-mode test asks of the viewer (within 10%).
#include "render_fixture.h"

#include "app/frame_options.h"
#include "app/reference_run.h"
#include "image/metrics.h"
#include "reference/live_metrics.h"
#include "reference/progressive_reference.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <thread>

namespace rtlab {
namespace {

TEST(ProgressiveReference, LiveRmseOfAFrameMatchesTheSinglePassCompare) {
  // A hard shadow map under a spherical light of radius 0.3: its error (the missing penumbrae,
  // rmse about 0.04) dominates the reference's own noise, as in a lecture's A/B comparison.
  constexpr int kSize = 128;
  TestFrame f = makeTestFrame("contact", "shadow_map", {"light0.radius=0.3"}, kSize, kSize);
  TestRender r = renderTestFrame(f, {"visibility"});
  const Image frame = r.renderer->readAov("visibility");
  const ResolvedFrame resolved = resolvedOf(f);
  const double compareRmse =
      computeMetrics(renderReferenceFrame(*r.renderer, resolved, "visibility", 256, false), frame).rmse;

  const ReferenceInput input = referenceInput(*r.renderer, resolved);
  ProgressiveReference reference;
  ProgressiveOptions options;
  options.targetSpp = 64;
  reference.start(input.scene, input.surfaces, "visibility", options);
  ProgressiveSnapshot snapshot;
  LiveMetrics at16, at64;
  const auto start = std::chrono::steady_clock::now();
  while (!snapshot.converged && std::chrono::steady_clock::now() - start < std::chrono::seconds(120)) {
    if (!reference.latest(snapshot)) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      continue;
    }
    const LiveMetrics live = computeLiveMetrics(frame, snapshot);
    EXPECT_EQ(live.ready, snapshot.samples >= 16) << snapshot.samples << " spp: " << live.reason;
    if (live.ready && !at16.ready) at16 = live;
    if (snapshot.converged) at64 = live;
  }
  ASSERT_TRUE(at64.ready) << reference.error();
  std::printf("shadow_map vs contact reference: compare (256 spp) rmse %.4f, live rmse %.4f at %d spp, %.4f at 64\n",
              compareRmse, at16.metrics.rmse, at16.referenceSamples, at64.metrics.rmse);
  EXPECT_GT(compareRmse, 0.01); // the technique's error is real, not reference noise
  // The reference's noise adds to the measured MSE, so the live figure can be a little higher; 10%
  // is issue 5's tolerance for the viewer's figure. Measured on llvmpipe: compare 0.0370, live
  // 0.0374 at 16 spp and 0.0368 at 64 spp.
  EXPECT_NEAR(at64.metrics.rmse, compareRmse, 0.1 * compareRmse);
  EXPECT_NEAR(at16.metrics.rmse, compareRmse, 0.1 * compareRmse);
}

} // namespace
} // namespace rtlab
