// Helpers behind the sweep: FNV-1a hashing (reference cache keys), base64 (data: URIs), CSV
// fields, the Pareto front and chart axes.
#include "util/base64.h"
#include "util/chart.h"
#include "util/csv.h"
#include "util/hash.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace rtlab;

TEST(SweepUtil, Fnv1a64KnownValues) {
  EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(fnv1a64("foobar"), 0x85944171f73967e8ull);
  EXPECT_EQ(Fnv1a64().bytes("a", 1).hex(), "af63dc4c8601ec8c");
}

TEST(SweepUtil, HashTextIsLengthPrefixed) {
  EXPECT_NE(Fnv1a64().text("ab").text("c").value(), Fnv1a64().text("a").text("bc").value());
  EXPECT_NE(Fnv1a64().f64(0.0).value(), Fnv1a64().f64(-0.0).value());
  EXPECT_EQ(Fnv1a64().f64(0.1).value(), Fnv1a64().f64(0.1).value());
}

TEST(SweepUtil, Base64) {
  EXPECT_EQ(base64Encode(std::string("")), "");
  EXPECT_EQ(base64Encode(std::string("f")), "Zg==");
  EXPECT_EQ(base64Encode(std::string("fo")), "Zm8=");
  EXPECT_EQ(base64Encode(std::string("foo")), "Zm9v");
  EXPECT_EQ(base64Encode(std::string("foobar")), "Zm9vYmFy");
  EXPECT_EQ(base64Encode(std::string("\xff\xfe", 2)), "//4=");
}

TEST(SweepUtil, CsvQuotesOnlyWhenNeeded) {
  EXPECT_EQ(csvField("pcf"), "pcf");
  EXPECT_EQ(csvField("1,2,3"), "\"1,2,3\"");
  EXPECT_EQ(csvField("a\"b"), "\"a\"\"b\"");
  EXPECT_EQ(csvLine({"a", "", "1,2"}), "a,,\"1,2\"\n");
}

TEST(SweepUtil, ParetoFront) {
  // (ms, rmse)
  const std::vector<ChartPoint> pts = {{1, 0.5}, {2, 0.3}, {2, 0.4}, {3, 0.35}, {4, 0.1}, {0.5, NAN}, {5, 0.1}};
  EXPECT_EQ(paretoFront(pts), (std::vector<std::size_t>{0, 1, 4}));
  EXPECT_TRUE(paretoFront({}).empty());
  // Equal points: only the first.
  EXPECT_EQ(paretoFront({{1, 1}, {1, 1}}), (std::vector<std::size_t>{0}));
}

TEST(SweepUtil, NiceAxes) {
  const ChartAxis lin = niceLinearAxis(0, 0.37);
  EXPECT_DOUBLE_EQ(lin.min, 0);
  EXPECT_NEAR(lin.max, 0.4, 1e-12);
  ASSERT_GE(lin.ticks.size(), 3u);
  EXPECT_EQ(lin.ticks.front(), 0.0);
  const ChartAxis flat = niceLinearAxis(2, 2);
  EXPECT_LT(flat.min, 2);
  EXPECT_GT(flat.max, 2);
  const ChartAxis lg = niceLogAxis(0.3, 40);
  EXPECT_TRUE(lg.log);
  EXPECT_DOUBLE_EQ(lg.min, 0.1);
  EXPECT_DOUBLE_EQ(lg.max, 100);
  EXPECT_DOUBLE_EQ(axisFraction(lg, 1), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(axisFraction(lin, -1), 0.0); // clamped
}
