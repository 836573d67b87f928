// The live metrics' ready policy (framework/reference/live_metrics.h): figures only once the
// reference has enough samples and the frame's size, then exactly computeMetrics(reference,
// frame). (tests/cli/test_live_metrics_cli.cpp checks them against `rtlab compare`.)
#include "reference/live_metrics.h"
#include "util/error.h"

#include "test_util.h"

#include <gtest/gtest.h>

namespace rtlab {
namespace {

Image ramp(int w, int h, float offset) {
  Image im(w, h, 1);
  im.mask.assign(im.pixelCount(), 1.0f);
  for (std::size_t i = 0; i < im.pixelCount(); ++i)
    im.pixels[i] = 0.25f + 0.5f * float(i % 7) / 7.0f + offset;
  im.mask[3] = 0.0f;
  return im;
}

ProgressiveSnapshot snapshot(int samples, int w = 12, int h = 8) {
  ProgressiveSnapshot s;
  s.image = ramp(w, h, 0.0f);
  s.samples = samples;
  s.generation = 1;
  return s;
}

TEST(LiveMetrics, ReadyOnlyWithEnoughSamplesAndTheFramesSize) {
  const Image frame = ramp(12, 8, 0.05f);
  LiveMetrics live = computeLiveMetrics(frame, ProgressiveSnapshot{});
  EXPECT_FALSE(live.ready);
  EXPECT_EQ(live.reason, "no reference yet");

  live = computeLiveMetrics(frame, snapshot(8));
  EXPECT_FALSE(live.ready);
  EXPECT_EQ(live.reason, "reference has 8 of 16 spp");
  EXPECT_EQ(live.referenceSamples, 8);
  EXPECT_EQ(live.metrics.validPixels, 0u); // nothing measured

  live = computeLiveMetrics(ramp(10, 8, 0.05f), snapshot(32));
  EXPECT_FALSE(live.ready);
  EXPECT_EQ(live.reason, "reference is 12x8, frame is 10x8");

  LiveMetricsPolicy eager;
  eager.minSamples = 4;
  EXPECT_TRUE(computeLiveMetrics(frame, snapshot(8), eager).ready);

  live = computeLiveMetrics(frame, snapshot(16));
  ASSERT_TRUE(live.ready);
  EXPECT_EQ(live.reason, "");
  EXPECT_EQ(live.generation, 1u);
  const Metrics m = computeMetrics(snapshot(16).image, frame);
  EXPECT_EQ(live.metrics.rmse, m.rmse);
  EXPECT_EQ(live.metrics.flip, m.flip);
  EXPECT_EQ(live.metrics.validPixels, 12u * 8u - 1u); // the masked pixel is left out
  EXPECT_NEAR(live.metrics.rmse, 0.05, 1e-6);
}

TEST(LiveMetrics, RejectsAPolicyOutOfRange) {
  LiveMetricsPolicy policy;
  policy.minSamples = 0;
  test::checkCaught(test::catchError([&] { computeLiveMetrics(ramp(4, 4, 0.0f), snapshot(16, 4, 4), policy); }),
                    ExitCode::Usage, {"minSamples", "1..65536"});
}

} // namespace
} // namespace rtlab
