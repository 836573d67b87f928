// params/param_spec + param_set: value syntax of every type (docs/contract.md "Keys and values"), range
// checks (never clamped), JSON values, unknown keys, declaration errors, revision, toJson, --set.
#include "params/param_set.h"
#include "params/param_spec.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include "test_util.h"
#include <nlohmann/json.hpp>

#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

using namespace rtlab;
using rtlab::test::catchError;
using rtlab::test::Caught;
using rtlab::test::checkCaught;
using nlohmann::json;

namespace {


ParamSpec fSpec() { return ParamSpec::real("t.f", "F", 0.5, -2.0, 3.0); }
ParamSpec iSpec() { return ParamSpec::integer("t.i", "I", 4, -8, 16); }
ParamSpec bSpec() { return ParamSpec::boolean("t.b", "B", false); }
ParamSpec eSpec() { return ParamSpec::choice("t.e", "E", {"low", "mid", "high"}, 1); }
ParamSpec vSpec() { return ParamSpec::vector3("t.v", "V", {0, 1, 0}, -10.0, 10.0); }
ParamSpec cSpec() { return ParamSpec::color("t.c", "C", {1, 1, 1}); }

ParamSet allTypes() {
  ParamSet set;
  set.declare({fSpec(), iSpec(), bSpec(), eSpec(), vSpec(), cSpec()});
  return set;
}

double parse1(const ParamSpec& spec, const std::string& text) { return parseParamValue(spec, text).v[0]; }

} // namespace

// ---- text syntax -------------------------------------------------------------------------------

TEST(ParamParse, FloatDecimalForms) {
  const ParamSpec s = fSpec();
  EXPECT_EQ(parse1(s, "1.5"), 1.5);
  EXPECT_EQ(parse1(s, "-1.25"), -1.25);
  EXPECT_EQ(parse1(s, "2"), 2.0);
  EXPECT_EQ(parse1(s, "+0.25"), 0.25);
  EXPECT_EQ(parse1(s, ".5"), 0.5);
  EXPECT_EQ(parse1(s, "1e-3"), 1e-3);
  EXPECT_EQ(parse1(s, "-1.5E+0"), -1.5);
  EXPECT_EQ(parse1(s, "25e-1"), 2.5);
  EXPECT_EQ(parse1(s, "-2"), -2.0); // min
  EXPECT_EQ(parse1(s, "3"), 3.0);   // max
}

TEST(ParamParse, IntDecimalForms) {
  const ParamSpec s = iSpec();
  EXPECT_EQ(parse1(s, "7"), 7.0);
  EXPECT_EQ(parse1(s, "-5"), -5.0);
  EXPECT_EQ(parse1(s, "+3"), 3.0);
  EXPECT_EQ(parse1(s, "0"), 0.0);
  EXPECT_EQ(parse1(s, "-8"), -8.0); // min
  EXPECT_EQ(parse1(s, "16"), 16.0); // max
}

TEST(ParamParse, BoolForms) {
  const ParamSpec s = bSpec();
  for (const char* t : {"true", "1", "on"}) EXPECT_EQ(parse1(s, t), 1.0) << t;
  for (const char* t : {"false", "0", "off"}) EXPECT_EQ(parse1(s, t), 0.0) << t;
}

TEST(ParamParse, EnumByName) {
  const ParamSpec s = eSpec();
  EXPECT_EQ(parse1(s, "low"), 0.0);
  EXPECT_EQ(parse1(s, "mid"), 1.0);
  EXPECT_EQ(parse1(s, "high"), 2.0);
}

TEST(ParamParse, Vec3AndColorForms) {
  EXPECT_EQ(parseParamValue(vSpec(), "1,2,3"), ParamValue::vec3({1, 2, 3}));
  EXPECT_EQ(parseParamValue(vSpec(), "-1.5,0,1e-2").v, (std::array<double, 3>{-1.5, 0.0, 1e-2}));
  EXPECT_EQ(parseParamValue(vSpec(), "-10,10,-10").v, (std::array<double, 3>{-10, 10, -10}));
  EXPECT_EQ(parseParamValue(cSpec(), "0.1,0.2,0.3").v, (std::array<double, 3>{0.1, 0.2, 0.3}));
  EXPECT_EQ(parseParamValue(cSpec(), "0,1,0").v, (std::array<double, 3>{0, 1, 0}));
}

TEST(ParamParse, FloatRejectsBadSyntax) {
  const ParamSpec s = fSpec();
  for (const char* t : {"abc", "", "nan", "NaN", "inf", "-inf", "infinity", "1.5x", "1,2", "0x1", "+-1", "--1",
                        "1e400", "1.2.3"})
    EXPECT_RTLAB_ERROR(parseParamValue(s, t), ExitCode::Usage, "'t.f'", "[-2, 3]");
}

TEST(ParamParse, IntRejectsBadSyntax) {
  const ParamSpec s = iSpec();
  for (const char* t : {"1.5", "abc", "", "1e2", "nan", "inf", "+-1", "3x", "0x4", "99999999999999999999999"})
    EXPECT_RTLAB_ERROR(parseParamValue(s, t), ExitCode::Usage, "'t.i'", "[-8, 16]");
}

TEST(ParamParse, BoolRejectsBadSyntax) {
  for (const char* t : {"yes", "no", "TRUE", "2", "", "-1", "1.0"})
    EXPECT_RTLAB_ERROR(parseParamValue(bSpec(), t), ExitCode::Usage, "'t.b'", "true|false|1|0|on|off");
}

TEST(ParamParse, EnumRejectsUnknownNames) {
  for (const char* t : {"medium", "", "HIGH", "2", "low "})
    EXPECT_RTLAB_ERROR(parseParamValue(eSpec(), t), ExitCode::Usage, "'t.e'", "one of: low, mid, high");
}

TEST(ParamParse, Vec3RejectsBadSyntax) {
  for (const char* t : {"2,3", "1,2,3,4", "1,,3", ",1,2", "1,2,", "a,b,c", "nan,0,0", "0,inf,0", "", "1 2 3", "abc"})
    EXPECT_RTLAB_ERROR(parseParamValue(vSpec(), t), ExitCode::Usage, "'t.v'", "[-10, 10]");
  EXPECT_RTLAB_ERROR(parseParamValue(cSpec(), "2,3"), ExitCode::Usage, "'t.c'", "[0, 1]");
}

// ---- ranges ------------------------------------------------------------------------------------

TEST(ParamRange, OutOfRangeTextRejectedNamingKeyAndRange) {
  EXPECT_RTLAB_ERROR(parseParamValue(fSpec(), "3.5"), ExitCode::Usage, "'t.f'", "[-2, 3]");
  EXPECT_RTLAB_ERROR(parseParamValue(fSpec(), "-2.5"), ExitCode::Usage, "'t.f'", "[-2, 3]");
  EXPECT_RTLAB_ERROR(parseParamValue(iSpec(), "17"), ExitCode::Usage, "'t.i'", "[-8, 16]");
  EXPECT_RTLAB_ERROR(parseParamValue(iSpec(), "-9"), ExitCode::Usage, "'t.i'", "[-8, 16]");
  EXPECT_RTLAB_ERROR(parseParamValue(vSpec(), "0,10.5,0"), ExitCode::Usage, "'t.v'", "[-10, 10]");
  EXPECT_RTLAB_ERROR(parseParamValue(cSpec(), "1,1,1.5"), ExitCode::Usage, "'t.c'", "[0, 1]");
  EXPECT_RTLAB_ERROR(parseParamValue(cSpec(), "-0.5,0,0"), ExitCode::Usage, "'t.c'", "[0, 1]");
}

TEST(ParamRange, JustOutsideBoundsRejectedAndShownExactly) {
  // min - 1e-9 and max + 1e-9: rejected, and the message must not print the value as the bound.
  EXPECT_RTLAB_ERROR(parseParamValue(fSpec(), "3.000000001"), ExitCode::Usage, "'t.f'", "[-2, 3]", "3.000000001");
  EXPECT_RTLAB_ERROR(parseParamValue(fSpec(), "-2.000000001"), ExitCode::Usage, "'t.f'", "[-2, 3]", "-2.000000001");
  EXPECT_RTLAB_ERROR(checkParamRange(fSpec(), ParamValue::scalar(3.0 + 1e-9)), ExitCode::Usage, "'t.f'", "[-2, 3]");
  EXPECT_RTLAB_ERROR(checkParamRange(fSpec(), ParamValue::scalar(-2.0 - 1e-9)), ExitCode::Usage, "'t.f'", "[-2, 3]");
  EXPECT_RTLAB_ERROR(parseParamValue(vSpec(), "0,10.000000001,0"), ExitCode::Usage, "'t.v'", "10.000000001");
  EXPECT_RTLAB_ERROR(parseParamValue(cSpec(), "-0.000000001,0,0"), ExitCode::Usage, "'t.c'", "-1e-09");
  ParamSpec small = ParamSpec::real("t.small", "S", 0.001, 0.0, 0.05);
  EXPECT_RTLAB_ERROR(parseParamValue(small, "0.050000001"), ExitCode::Usage, "'t.small'", "[0, 0.05]");
  EXPECT_EQ(parse1(small, "0.05"), 0.05);
  EXPECT_EQ(parse1(small, "0"), 0.0);
}

TEST(ParamRange, NeverClampedValueKeptOnRejection) {
  ParamSet set = allTypes();
  EXPECT_RTLAB_ERROR(set.setText("t.f", "3.000000001"), ExitCode::Usage, "'t.f'");
  EXPECT_EQ(set.value("t.f").v[0], 0.5);
  EXPECT_RTLAB_ERROR(set.set("t.f", ParamValue::scalar(-1e9)), ExitCode::Usage, "'t.f'");
  EXPECT_EQ(set.value("t.f").v[0], 0.5);
  EXPECT_RTLAB_ERROR(set.set("t.i", ParamValue::scalar(2.5)), ExitCode::Usage, "'t.i'", "integer");
  EXPECT_EQ(set.getInt("t.i"), 4);
  EXPECT_RTLAB_ERROR(set.set("t.e", ParamValue::scalar(3)), ExitCode::Usage, "'t.e'", "one of: low, mid, high");
  EXPECT_RTLAB_ERROR(set.set("t.e", ParamValue::scalar(-1)), ExitCode::Usage, "'t.e'");
  EXPECT_EQ(set.getEnumName("t.e"), "mid");
  EXPECT_RTLAB_ERROR(set.set("t.f", ParamValue::scalar(std::nan(""))), ExitCode::Usage, "'t.f'");
  EXPECT_EQ(set.value("t.f").v[0], 0.5);
}

TEST(ParamRange, BoundsThemselvesAccepted) {
  ParamSet set = allTypes();
  set.setText("t.f", "-2");
  EXPECT_EQ(set.getFloat("t.f"), -2.0f);
  set.setText("t.f", "3");
  EXPECT_EQ(set.getFloat("t.f"), 3.0f);
  set.setText("t.i", "-8");
  EXPECT_EQ(set.getInt("t.i"), -8);
  set.setText("t.i", "16");
  EXPECT_EQ(set.getInt("t.i"), 16);
  set.setText("t.v", "-10,10,-10");
  EXPECT_EQ(set.getVec3("t.v"), glm::vec3(-10, 10, -10));
  set.setText("t.c", "0,1,0");
  EXPECT_EQ(set.getVec3("t.c"), glm::vec3(0, 1, 0));
  set.setText("t.e", "low");
  EXPECT_EQ(set.getEnum("t.e"), 0);
  set.setText("t.e", "high");
  EXPECT_EQ(set.getEnum("t.e"), 2);
}

TEST(ParamFormat, EnumIndexOutsideChoicesIsSafe) {
  const ParamSpec e = eSpec();
  EXPECT_EQ(formatParamValue(e, ParamValue::scalar(2)), "high");
  EXPECT_EQ(formatParamValue(e, ParamValue::scalar(-1)), "-1");
  EXPECT_EQ(formatParamValue(e, ParamValue::scalar(7)), "7");
  EXPECT_EQ(formatParamValue(bSpec(), ParamValue::scalar(1)), "true");
  EXPECT_EQ(formatParamValue(vSpec(), ParamValue::vec3({1, -2, 0.5f})), "1,-2,0.5");
}

// ---- JSON values -------------------------------------------------------------------------------

TEST(ParamJson, AcceptsEveryTypesJsonForm) {
  EXPECT_EQ(paramValueFromJson(fSpec(), json(1.25)).v[0], 1.25);
  EXPECT_EQ(paramValueFromJson(fSpec(), json(-2)).v[0], -2.0);
  EXPECT_EQ(paramValueFromJson(fSpec(), json::parse("1e-3")).v[0], 1e-3);
  EXPECT_EQ(paramValueFromJson(iSpec(), json(16)).v[0], 16.0);
  EXPECT_EQ(paramValueFromJson(iSpec(), json(-8)).v[0], -8.0);
  EXPECT_EQ(paramValueFromJson(bSpec(), json(true)).v[0], 1.0);
  EXPECT_EQ(paramValueFromJson(bSpec(), json(false)).v[0], 0.0);
  EXPECT_EQ(paramValueFromJson(eSpec(), json("high")).v[0], 2.0);
  EXPECT_EQ(paramValueFromJson(vSpec(), json::parse("[1, -2.5, 1e-2]")).v, (std::array<double, 3>{1, -2.5, 1e-2}));
  EXPECT_EQ(paramValueFromJson(cSpec(), json::parse("[0.1, 0.2, 0]")).v, (std::array<double, 3>{0.1, 0.2, 0}));
}

TEST(ParamJson, RejectsWrongJsonTypes) {
  for (const char* t : {"\"1.5\"", "true", "null", "[1]", "{}"})
    EXPECT_RTLAB_ERROR(paramValueFromJson(fSpec(), json::parse(t)), ExitCode::Usage, "'t.f'", "[-2, 3]");
  for (const char* t : {"\"4\"", "false", "null", "2.5"})
    EXPECT_RTLAB_ERROR(paramValueFromJson(iSpec(), json::parse(t)), ExitCode::Usage, "'t.i'", "[-8, 16]");
  for (const char* t : {"\"true\"", "null", "0.5", "2", "[true]"})
    EXPECT_RTLAB_ERROR(paramValueFromJson(bSpec(), json::parse(t)), ExitCode::Usage, "'t.b'");
  for (const char* t : {"1", "true", "null", "\"medium\"", "[\"low\"]"})
    EXPECT_RTLAB_ERROR(paramValueFromJson(eSpec(), json::parse(t)), ExitCode::Usage, "'t.e'", "one of: low, mid, high");
  for (const char* t : {"[1, 2]", "[1, 2, 3, 4]", "[1, 2, \"3\"]", "[1, null, 3]", "3", "\"1,2,3\"", "{}", "null"})
    EXPECT_RTLAB_ERROR(paramValueFromJson(vSpec(), json::parse(t)), ExitCode::Usage, "'t.v'", "[-10, 10]");
}

TEST(ParamJson, OutOfRangeJsonRejected) {
  EXPECT_RTLAB_ERROR(paramValueFromJson(fSpec(), json(3.000000001)), ExitCode::Usage, "'t.f'", "[-2, 3]");
  EXPECT_RTLAB_ERROR(paramValueFromJson(iSpec(), json(17)), ExitCode::Usage, "'t.i'", "[-8, 16]");
  EXPECT_RTLAB_ERROR(paramValueFromJson(cSpec(), json::parse("[0, 0, 1.5]")), ExitCode::Usage, "'t.c'", "[0, 1]");
}

TEST(ParamJson, ToJsonTypes) {
  EXPECT_TRUE(paramValueToJson(fSpec(), ParamValue::scalar(0.5)).is_number_float());
  EXPECT_TRUE(paramValueToJson(iSpec(), ParamValue::scalar(3)).is_number_integer());
  EXPECT_EQ(paramValueToJson(bSpec(), ParamValue::scalar(1)), json(true));
  EXPECT_EQ(paramValueToJson(eSpec(), ParamValue::scalar(0)), json("low"));
  EXPECT_EQ(paramValueToJson(vSpec(), ParamValue::vec3({1, 2, 3})), json::parse("[1.0, 2.0, 3.0]"));
}

TEST(ParamJson, SpecJsonHasContractFields) {
  const auto p = paramSpecToJson(ParamSpec::real("t.f", "F", 0.5, 0.0, 2.0).logScale().withUnit("m").withHelp("h"));
  for (const char* k : {"key", "type", "default", "min", "max", "scale", "unit", "help"}) EXPECT_TRUE(p.contains(k)) << k;
  EXPECT_EQ(p["type"], "float");
  EXPECT_EQ(p["scale"], "log");
  EXPECT_EQ(p["min"], 0.0);
  EXPECT_EQ(p["max"], 2.0);
  const auto e = paramSpecToJson(eSpec());
  EXPECT_EQ(e["type"], "enum");
  EXPECT_EQ(e["default"], "mid");
  EXPECT_EQ(e["choices"], nlohmann::ordered_json::parse(R"(["low","mid","high"])"));
  EXPECT_EQ(paramSpecToJson(iSpec())["min"], -8);
  EXPECT_EQ(paramSpecToJson(cSpec())["type"], "color");
}

// ---- ParamSet ----------------------------------------------------------------------------------

TEST(ParamSet, DefaultsAndGetters) {
  ParamSet set = allTypes();
  EXPECT_TRUE(set.has("t.f"));
  EXPECT_FALSE(set.has("t.g"));
  EXPECT_EQ(set.specs().size(), 6u);
  EXPECT_EQ(set.specs()[0].key, "t.f"); // declaration order
  EXPECT_EQ(set.getFloat("t.f"), 0.5f);
  EXPECT_EQ(set.getInt("t.i"), 4);
  EXPECT_FALSE(set.getBool("t.b"));
  EXPECT_EQ(set.getEnum("t.e"), 1);
  EXPECT_EQ(set.getEnumName("t.e"), "mid");
  EXPECT_EQ(set.getVec3("t.v"), glm::vec3(0, 1, 0));
  EXPECT_EQ(set.getVec3("t.c"), glm::vec3(1, 1, 1));
}

TEST(ParamSet, UnknownKeySuggestsNearMiss) {
  ParamSet set;
  set.declare({ParamSpec::integer("pcf.samples", "Samples", 16, 1, 64), ParamSpec::real("pcf.radius", "R", 1, 0, 8)});
  EXPECT_RTLAB_ERROR(set.setText("pcf.sample", "4"), ExitCode::Usage, "unknown key 'pcf.sample'",
                     "did you mean 'pcf.samples'");
  EXPECT_RTLAB_ERROR(set.setAssignment("pcf.raduis=2"), ExitCode::Usage, "'pcf.raduis'", "did you mean 'pcf.radius'");
  const Caught far = catchError([&] { set.setText("zzz.qqqqqqq", "1"); });
  checkCaught(far, ExitCode::Usage, {"unknown key 'zzz.qqqqqqq'"});
  EXPECT_EQ(far.message.find("did you mean"), std::string::npos) << far.message;
  EXPECT_RTLAB_ERROR(set.value("nope"), ExitCode::Usage, "'nope'");
  EXPECT_RTLAB_ERROR(set.spec("nope"), ExitCode::Usage, "'nope'");
  EXPECT_RTLAB_ERROR(set.setJson("pcf.sampels", json(4)), ExitCode::Usage, "did you mean 'pcf.samples'");
}

TEST(ParamSet, DuplicateDeclarationIsInternal) {
  ParamSet set = allTypes();
  EXPECT_RTLAB_ERROR(set.declare(ParamSpec::real("t.f", "F again", 0, 0, 1)), ExitCode::Internal, "'t.f'");
  EXPECT_RTLAB_ERROR(set.declare(ParamSpec::boolean("t.i", "other type", true)), ExitCode::Internal, "'t.i'");
  EXPECT_EQ(set.specs().size(), 6u);
  EXPECT_EQ(set.getFloat("t.f"), 0.5f);
}

TEST(ParamSet, DefaultOutsideItsRangeIsInternal) {
  ParamSet set;
  EXPECT_RTLAB_ERROR(set.declare(ParamSpec::real("d.f", "F", 2.0, 0.0, 1.0)), ExitCode::Internal, "'d.f'");
  EXPECT_RTLAB_ERROR(set.declare(ParamSpec::real("d.g", "G", -1e-9, 0.0, 1.0)), ExitCode::Internal, "'d.g'");
  EXPECT_RTLAB_ERROR(set.declare(ParamSpec::integer("d.i", "I", 128, 256, 4096)), ExitCode::Internal, "'d.i'");
  EXPECT_RTLAB_ERROR(set.declare(ParamSpec::choice("d.e", "E", {"a", "b"}, 2)), ExitCode::Internal, "'d.e'");
  EXPECT_RTLAB_ERROR(set.declare(ParamSpec::choice("d.n", "N", {}, 0)), ExitCode::Internal, "'d.n'");
  EXPECT_RTLAB_ERROR(set.declare(ParamSpec::vector3("d.v", "V", {0, 2, 0}, -1, 1)), ExitCode::Internal, "'d.v'");
  EXPECT_RTLAB_ERROR(set.declare(ParamSpec::color("d.c", "C", {1.5f, 0, 0})), ExitCode::Internal, "'d.c'");
  EXPECT_RTLAB_ERROR(set.declare(ParamSpec::real("d.m", "M", 0.5, 1.0, 0.0)), ExitCode::Internal, "'d.m'");
  EXPECT_RTLAB_ERROR(set.declare(ParamSpec::real("d.nan", "NaN", std::nan(""), 0.0, 1.0)), ExitCode::Internal, "'d.nan'");
  EXPECT_TRUE(set.specs().empty());
  // Defaults at the bounds are fine.
  set.declare({ParamSpec::real("d.lo", "L", 0.0, 0.0, 1.0), ParamSpec::real("d.hi", "H", 1.0, 0.0, 1.0),
               ParamSpec::integer("d.r", "R", 4096, 256, 4096)});
  EXPECT_EQ(set.specs().size(), 3u);
}

TEST(ParamSet, RevisionBumpsOnChangeOnly) {
  ParamSet set = allTypes();
  const auto r0 = set.revision();
  set.setText("t.f", "0.5"); // same value
  set.set("t.i", ParamValue::scalar(4));
  set.setText("t.b", "off");
  set.setText("t.e", "mid");
  set.setJson("t.v", json::parse("[0, 1, 0]"));
  set.reset("t.c");
  EXPECT_EQ(set.revision(), r0);
  set.setText("t.f", "0.75");
  EXPECT_EQ(set.revision(), r0 + 1);
  set.setText("t.f", "0.75");
  EXPECT_EQ(set.revision(), r0 + 1);
  EXPECT_RTLAB_ERROR(set.setText("t.f", "9"), ExitCode::Usage, "'t.f'");
  EXPECT_EQ(set.revision(), r0 + 1); // a rejected value changes nothing
  set.setText("t.v", "1,1,0");
  EXPECT_EQ(set.revision(), r0 + 2);
  set.reset("t.f");
  EXPECT_EQ(set.revision(), r0 + 3);
  EXPECT_EQ(set.getFloat("t.f"), 0.5f);
  set.reset("t.f");
  EXPECT_EQ(set.revision(), r0 + 3);
}

TEST(ParamSet, ToJsonPrefixFilter) {
  ParamSet set;
  set.declare({ParamSpec::integer("pcf.samples", "S", 16, 1, 64), ParamSpec::real("pcf.radius", "R", 1, 0, 8),
               ParamSpec::real("pcss.light_size", "L", 1, 0, 8), ParamSpec::integer("shadow.resolution", "Res", 2048, 256, 4096),
               ParamSpec::boolean("shadow.cull_front", "C", true), eSpec(), vSpec()});
  const json pcf = set.toJson({"pcf."});
  EXPECT_EQ(pcf.size(), 2u);
  EXPECT_EQ(pcf["pcf.samples"], 16);
  EXPECT_EQ(pcf["pcf.radius"], 1.0);
  EXPECT_FALSE(pcf.contains("pcss.light_size"));
  const json two = set.toJson({"pcf.", "shadow."});
  EXPECT_EQ(two.size(), 4u);
  EXPECT_EQ(two["shadow.cull_front"], true);
  const json all = set.toJson();
  EXPECT_EQ(all.size(), 7u);
  EXPECT_EQ(all["t.e"], "mid");
  EXPECT_EQ(all["t.v"], json::parse("[0.0, 1.0, 0.0]"));
  EXPECT_TRUE(set.toJson({"nothing."}).empty());
  EXPECT_TRUE(set.toJson({"nothing."}).is_object());
}

TEST(ParamSet, SetAssignment) {
  ParamSet set = allTypes();
  set.setAssignment("t.f=1.25");
  EXPECT_EQ(set.getFloat("t.f"), 1.25f);
  set.setAssignment("t.v=1,2,3");
  EXPECT_EQ(set.getVec3("t.v"), glm::vec3(1, 2, 3));
  set.setAssignment("t.e=high");
  EXPECT_EQ(set.getEnumName("t.e"), "high");
  set.setAssignment("t.b=on");
  EXPECT_TRUE(set.getBool("t.b"));
  set.setAssignment("t.i=-3");
  EXPECT_EQ(set.getInt("t.i"), -3);
}

TEST(ParamSet, MalformedAssignmentRejected) {
  ParamSet set = allTypes();
  EXPECT_RTLAB_ERROR(set.setAssignment("t.f"), ExitCode::Usage, "KEY=VALUE", "'t.f'");
  EXPECT_RTLAB_ERROR(set.setAssignment("=1"), ExitCode::Usage, "KEY=VALUE", "'=1'");
  EXPECT_RTLAB_ERROR(set.setAssignment(""), ExitCode::Usage, "KEY=VALUE");
  EXPECT_RTLAB_ERROR(set.setAssignment("t.f="), ExitCode::Usage, "'t.f'", "[-2, 3]");
  EXPECT_RTLAB_ERROR(set.setAssignment("t.f==1"), ExitCode::Usage, "'t.f'");
  EXPECT_RTLAB_ERROR(set.setAssignment("t.v=2,3"), ExitCode::Usage, "'t.v'", "x,y,z");
  EXPECT_RTLAB_ERROR(set.setAssignment("t.i=1.5"), ExitCode::Usage, "'t.i'", "[-8, 16]");
  EXPECT_RTLAB_ERROR(set.setAssignment("t.x=1"), ExitCode::Usage, "unknown key 't.x'");
  EXPECT_EQ(set.getFloat("t.f"), 0.5f);
}
