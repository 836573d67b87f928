// The sweep's heat-map scale (util/percentile.h, docs/sweeps.md "report.html"): percentiles of a
// stream within a bin (about 2%) of the exact ones, and one outlier does not move a high
// percentile, which is why the heat maps use it instead of the largest error.
#include "util/percentile.h"

#include <gtest/gtest.h>

#include <limits>

using namespace rtlab;

TEST(ErrorPercentile, NearTheExactPercentile) {
  ErrorPercentile p;
  for (int i = 1; i <= 1000; ++i) p.add(float(i) / 1000.0f); // 0.001 .. 1
  EXPECT_EQ(p.count(), 1000u);
  EXPECT_NEAR(p.percentile(0.5), 0.5, 0.5 * 0.025);
  EXPECT_NEAR(p.percentile(0.99), 0.99, 0.99 * 0.025);
  EXPECT_GE(p.percentile(0.99), 0.99) << "a bin's upper edge: never below the exact value";
  EXPECT_DOUBLE_EQ(p.percentile(1.0), 1.0) << "at most the largest value";
}

TEST(ErrorPercentile, OneOutlierDoesNotMoveTheScale) {
  ErrorPercentile p;
  for (int i = 0; i < 10000; ++i) p.add(0.05f + 0.05f * float(i % 10) / 10.0f); // 0.05 .. 0.095
  p.add(1.0f);                                                                   // one speckle
  EXPECT_DOUBLE_EQ(p.max(), 1.0);
  EXPECT_LT(p.percentile(0.99), 0.1);
  EXPECT_GT(p.percentile(0.99), 0.09);
}

TEST(ErrorPercentile, ZerosAndNonFiniteValuesAreNotCounted) {
  ErrorPercentile p;
  EXPECT_EQ(p.percentile(0.99), 0.0);
  p.add(0.0f);
  p.add(-1.0f);
  p.add(std::numeric_limits<float>::quiet_NaN());
  p.add(std::numeric_limits<float>::infinity());
  EXPECT_EQ(p.count(), 0u);
  p.add(0.25f);
  EXPECT_DOUBLE_EQ(p.percentile(0.99), 0.25);
}
