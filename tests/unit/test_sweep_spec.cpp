// Sweep axes and grids (params/sweep_spec.h): value lists and LO:HI:N ranges validated against
// each key's declaration, linear and log spacing, which keys apply to which technique, and the cross
// product. Which keys define the reference: test_reference_registry.cpp.
#include "params/sweep_spec.h"
#include "util/error.h"

#include <gtest/gtest.h>

using namespace rtlab;

namespace {

using Strings = std::vector<std::string>;

int usageExit(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return int(e.code());
  }
  return 0;
}

std::string usageMessage(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::Usage) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return "";
}

const ParamSpec kRes = ParamSpec::integer("shadow.resolution", "Res", 2048, 256, 4096).logScale();
const ParamSpec kBias = ParamSpec::real("shadow.constant_bias", "Bias", 0.001, 0.0, 0.05);
const ParamSpec kRadius = ParamSpec::real("ao.radius", "Radius", 0.5, 0.01, 10.0).logScale();
const ParamSpec kFormat = ParamSpec::choice("shadow.depth_format", "Format", {"16", "24", "32f"}, 1);
const ParamSpec kCull = ParamSpec::boolean("shadow.cull_front", "Cull", false);
const ParamSpec kColor = ParamSpec::color("light0.color", "Color", {1, 1, 1}, 0, 100);

} // namespace

TEST(SweepSpec, SplitsKeyAndSpec) {
  EXPECT_EQ(splitVaryArgument("a.b=1,2"), (std::pair<std::string, std::string>{"a.b", "1,2"}));
  EXPECT_EQ(usageExit([] { splitVaryArgument("a.b"); }), 2);
  EXPECT_EQ(usageExit([] { splitVaryArgument("=1"); }), 2);
  EXPECT_EQ(usageExit([] { splitVaryArgument("a.b="); }), 2);
}

TEST(SweepSpec, ListsAreCanonicalAndDeduplicated) {
  EXPECT_EQ(expandSweepValues(kBias, "0.010,0.001,0.01"), (Strings{"0.01", "0.001"}));
  EXPECT_EQ(expandSweepValues(kRes, "512,1024"), (Strings{"512", "1024"}));
  EXPECT_EQ(expandSweepValues(kFormat, "16,32f"), (Strings{"16", "32f"}));
  EXPECT_EQ(expandSweepValues(kCull, "on,0"), (Strings{"true", "false"}));
  EXPECT_EQ(expandSweepValues(kColor, "1,1,1;0.5,0.25,1"), (Strings{"1,1,1", "0.5,0.25,1"}));
}

TEST(SweepSpec, ValuesOutOfRangeNameTheKeyAndRange) {
  const std::string m = usageMessage([] { expandSweepValues(kRes, "128,512"); });
  EXPECT_NE(m.find("shadow.resolution"), std::string::npos) << m;
  EXPECT_NE(m.find("[256, 4096]"), std::string::npos) << m;
  EXPECT_EQ(usageExit([] { expandSweepValues(kRes, "300:9000:3"); }), 2);
  EXPECT_EQ(usageExit([] { expandSweepValues(kRes, "300.5"); }), 2); // ints are integers
  EXPECT_EQ(usageExit([] { expandSweepValues(kFormat, "8"); }), 2);
  EXPECT_EQ(usageExit([] { expandSweepValues(kBias, "0.1,"); }), 2);
}

TEST(SweepSpec, LinearRange) {
  EXPECT_EQ(expandSweepValues(kBias, "0:0.04:5"), (Strings{"0", "0.01", "0.02", "0.03", "0.04"}));
  EXPECT_EQ(expandSweepValues(kBias, "0.04:0:3"), (Strings{"0.04", "0.02", "0"})); // descending is allowed
}

TEST(SweepSpec, LogRangeFollowsTheDeclaredScale) {
  EXPECT_EQ(expandSweepValues(kRes, "256:4096:5"), (Strings{"256", "512", "1024", "2048", "4096"}));
  EXPECT_EQ(expandSweepValues(kRadius, "0.01:1:5"), (Strings{"0.01", "0.0316228", "0.1", "0.316228", "1"}));
  // Rounding ints can repeat a value: duplicates go.
  EXPECT_EQ(expandSweepValues(kRes, "256:258:5"), (Strings{"256", "257", "258"}));
  EXPECT_EQ(usageExit([] { expandSweepValues(kRadius, "0:1:3"); }), 2); // out of its range first
  const ParamSpec gain = ParamSpec::real("post.gain", "Gain", 1, 0, 10).logScale();
  const std::string m = usageMessage([&] { expandSweepValues(gain, "0:1:3"); });
  EXPECT_NE(m.find("log"), std::string::npos) << m;
}

TEST(SweepSpec, RangeNeedsTwoPointsAndNumbers) {
  EXPECT_EQ(usageExit([] { expandSweepValues(kBias, "0:0.04:1"); }), 2);
  EXPECT_EQ(usageExit([] { expandSweepValues(kBias, "0:0.04:x"); }), 2);
  EXPECT_EQ(usageExit([] { expandSweepValues(kBias, "0:0.04"); }), 2);
  EXPECT_EQ(usageExit([] { expandSweepValues(kFormat, "16:32f:2"); }), 2); // enums only by list
  EXPECT_EQ(usageExit([] { expandSweepValues(kCull, "0:1:2"); }), 2);
}

TEST(SweepSpec, CanonicalTextReadsBackExactly) {
  for (const auto& v : expandSweepValues(kRadius, "0.01:10:17")) {
    const ParamValue p = parseParamValue(kRadius, v);
    EXPECT_EQ(canonicalParamText(kRadius, p), v);
  }
}

TEST(SweepSpec, WhichKeysApply) {
  const SweepTechnique pcf{"pcf", "shadow"};
  EXPECT_TRUE(sweepKeyApplies("pcf.samples", pcf));
  EXPECT_TRUE(sweepKeyApplies("shadow.resolution", pcf));
  EXPECT_TRUE(sweepKeyApplies("tonemap.exposure", pcf));
  EXPECT_TRUE(sweepKeyApplies("light12.radius", pcf));
  EXPECT_TRUE(sweepKeyApplies("camera.fov", pcf));
  EXPECT_FALSE(sweepKeyApplies("pcss.samples", pcf));
  EXPECT_FALSE(sweepKeyApplies("ao.radius", pcf));
  EXPECT_FALSE(sweepKeyApplies("lightx.radius", pcf));
}

TEST(SweepSpec, GridIsACrossProductPerTechnique) {
  const std::vector<SweepTechnique> techniques = {{"pcf", "shadow"}, {"pcss", "shadow"}};
  const std::vector<SweepAxis> axes = {{"shadow.resolution", "", {"512", "1024"}},
                                       {"pcf.samples", "", {"4", "16", "64"}},
                                       {"light0.radius", "", {"0.1"}}};
  const auto grid = buildSweepGrid(techniques, axes);
  ASSERT_EQ(grid.size(), 2u * 3u + 2u);
  EXPECT_EQ(grid[0].technique, "pcf");
  using Values = std::vector<std::pair<std::string, std::string>>;
  EXPECT_EQ(grid[0].values, (Values{{"shadow.resolution", "512"}, {"pcf.samples", "4"}, {"light0.radius", "0.1"}}));
  EXPECT_EQ(grid[1].values[1].second, "16"); // the last axis varies fastest
  EXPECT_EQ(grid[3].values[0].second, "1024");
  EXPECT_EQ(grid[6].technique, "pcss"); // pcf's key is left out of pcss's grid
  EXPECT_EQ(grid[6].values, (Values{{"shadow.resolution", "512"}, {"light0.radius", "0.1"}}));
}

TEST(SweepSpec, GridRejectsKeysThatAffectNoTechnique) {
  const std::vector<SweepTechnique> techniques = {{"pcf", "shadow"}};
  const std::string m = usageMessage([&] { buildSweepGrid(techniques, {{"ao.radius", "", {"1"}}}); });
  EXPECT_NE(m.find("ao.radius"), std::string::npos) << m;
  EXPECT_EQ(usageExit([&] { buildSweepGrid(techniques, {{"pcf.samples", "", {"1"}}, {"pcf.samples", "", {"2"}}}); }), 2);
  EXPECT_EQ(usageExit([&] {
              buildSweepGrid(techniques, {{"pcf.a", "", Strings(100, "1")}, {"pcf.b", "", Strings(100, "1")}}, 1000);
            }),
            2);
}

TEST(SweepSpec, NoAxesGiveOnePointPerTechnique) {
  const auto grid = buildSweepGrid({{"pcf", "shadow"}, {"pcss", "shadow"}}, {});
  ASSERT_EQ(grid.size(), 2u);
  EXPECT_TRUE(grid[0].values.empty());
}
