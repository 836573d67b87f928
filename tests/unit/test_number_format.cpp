// util/number_format and util/suggest: the numbers and "did you mean" hints every user message
// uses (docs/cli.md "Numbers in messages", "Mistyped names").
#include "params/param_set.h"
#include "params/param_spec.h"
#include "util/number_format.h"
#include "util/suggest.h"

#include <gtest/gtest.h>

#include "test_util.h"

#include <cstdlib>
#include <string>
#include <vector>

using namespace rtlab;

TEST(NumberFormat, IntegersPrintAsIntegers) {
  EXPECT_EQ(formatNumber(100000.0), "100000"); // std::to_chars alone gives "1e+05"
  EXPECT_EQ(formatNumber(1000000.0), "1000000");
  EXPECT_EQ(formatNumber(-4096.0), "-4096");
  EXPECT_EQ(formatNumber(0.0), "0");
  EXPECT_EQ(formatNumber(-0.0), "0");
  EXPECT_EQ(formatNumberExact(100000.0), "100000");
}

TEST(NumberFormat, FloatsPrintAsTheirShortestForm) {
  EXPECT_EQ(formatNumber(0.1f), "0.1");             // not 0.100000001 (9 digits of the float)
  EXPECT_EQ(formatNumber(double(0.1f)), "0.1");     // a float widened to double: still the float
  EXPECT_EQ(formatNumber(double(8.544f)), "8.544"); // not 8.54400349
  EXPECT_EQ(formatNumber(0.03), "0.03");
  EXPECT_EQ(formatNumber(2.5e-7), "2.5e-07");
}

TEST(NumberFormat, ReadsBackAsTheValue) {
  // A value just outside a bound must not print as the bound (1 + 1e-9 is not "1").
  EXPECT_EQ(formatNumber(1.0 + 1e-9), "1.000000001");
  for (double v : {0.1, 1.0 / 3.0, 1e-300, 123456.789, 0.30000000000000004})
    EXPECT_EQ(std::strtod(formatNumberExact(v).c_str(), nullptr), v) << v;
  // The exact form of a widened float reads back as that double, not the float's short form.
  EXPECT_EQ(std::strtod(formatNumberExact(double(0.1f)).c_str(), nullptr), double(0.1f));
}

TEST(NumberFormat, RangesInParameterMessages) {
  const ParamSpec coord = ParamSpec::vector3("camera.position", "P", glm::vec3(0), -1.0e5, 1.0e5);
  EXPECT_EQ(describeRange(coord), "x,y,z each in [-100000, 100000]");
  const ParamSpec radius = ParamSpec::real("light0.radius", "R", double(0.1f), 0.0, double(8.544f));
  EXPECT_EQ(describeRange(radius), "range [0, 8.544]");
  EXPECT_EQ(formatParamValue(radius, radius.def), "0.1");
  EXPECT_RTLAB_ERROR(parseParamValue(radius, "100000"), ExitCode::Usage, "value 100000 for 'light0.radius'",
                     "[0, 8.544]");
}

TEST(Suggest, ClosestNameIgnoresCaseAndSmallTypos) {
  const std::vector<std::string> techniques = {"shadow_map", "pcf", "pcss", "vssm", "msm", "ssao", "hbao", "none"};
  EXPECT_EQ(closestName("shadowmap", techniques), "shadow_map");
  EXPECT_EQ(closestName("PCSS", techniques), "pcss");
  EXPECT_EQ(closestName("Contact", {"contact", "stacked", "cornell"}), "contact");
  EXPECT_EQ(closestName("visibilty", {"color", "visibility", "ao", "depth"}), "visibility");
  // Far from everything, or a change of more than half the typed text: no guess.
  EXPECT_EQ(closestName("no_such_technique", techniques), "");
  EXPECT_EQ(closestName("x", {"ao"}), "");
  EXPECT_EQ(didYouMean("zzz", techniques, " (see list)"), " (see list)");
  EXPECT_EQ(didYouMean("pcs", techniques), " (did you mean 'pcf'?)"); // first of the closest, in order
}

TEST(Suggest, KeysUseTheSameHelper) {
  ParamSet set;
  set.declare({ParamSpec::integer("shadow.resolution", "R", 1024, 256, 4096)});
  EXPECT_RTLAB_ERROR(set.setText("Shadow.Resolution", "512"), ExitCode::Usage, "did you mean 'shadow.resolution'");
}
