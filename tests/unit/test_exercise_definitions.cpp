// Exercise definitions and course authors' view files (docs/exercises.md "Definitions").
#include "exercise/exercise_def.h"
#include "test_util.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace rtlab;
using rtlab::test::catchError;
using rtlab::test::checkCaught;

namespace {
const char* kDef = R"({"schema": 1, "id": "demo", "technique": "pcf", "title": "Demo", "regions": ["pcf-filter"],
  "aov": "visibility", "background": ["one", "two"], "tolerance": {"pixel": 0.05}, "time_limit_s": 12,
  "views": [{"name": "a", "scene": "contact"},
            {"name": "b", "scene": "stacked", "size": "64x32", "set": {"pcf.radius": "8", "pcf.samples": 4},
             "techniques": ["pcf", "ssao"], "seed": 3, "spp": 16, "hidden": true, "note": "extreme"}]})";

std::string replaced(const std::string& find, const std::string& replace) {
  return rtlab::test::replacedOnce(kDef, find, replace);
}
} // namespace

TEST(ExerciseDefinitions, ParsesEveryField) {
  const ExerciseDef d = parseExerciseDef(kDef, "demo.json");
  EXPECT_EQ(d.id, "demo");
  EXPECT_EQ(d.technique, "pcf");
  EXPECT_EQ(d.aov, "visibility");
  EXPECT_EQ(d.background.size(), 2u);
  EXPECT_DOUBLE_EQ(d.tolerance.pixel, 0.05);
  EXPECT_DOUBLE_EQ(d.tolerance.fraction, ExerciseTolerance{}.fraction); // defaults where not given
  EXPECT_DOUBLE_EQ(d.timeLimitSeconds, 12.0);
  ASSERT_EQ(d.views.size(), 2u);
  EXPECT_EQ(d.views[0].width, 160);
  EXPECT_EQ(d.views[0].height, 90);
  EXPECT_FALSE(d.views[0].hidden);
  const ExerciseView& b = d.views[1];
  EXPECT_EQ(b.width, 64);
  EXPECT_EQ(b.height, 32);
  EXPECT_EQ(b.set.size(), 2u);
  EXPECT_EQ(b.techniques, (std::vector<std::string>{"pcf", "ssao"}));
  EXPECT_EQ(b.seed, 3u);
  EXPECT_EQ(b.spp, 16);
  EXPECT_TRUE(b.hidden);
  // Views survive the round trip to the worker processes.
  const auto back = viewsFromJson(viewsToJson(d.views), "round trip");
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1].set, b.set);
  EXPECT_EQ(back[1].techniques, b.techniques);
  EXPECT_EQ(back[1].spp, 16);
  EXPECT_EQ(viewSize(back[1]), "64x32");
}

TEST(ExerciseDefinitions, BadDefinitionsAreInputErrorsNamingTheFile) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{", "invalid JSON"},
      {replaced("\"schema\": 1", "\"schema\": 2"), "\"schema\" must be 1"},
      {replaced("\"title\": \"Demo\", ", ""), "missing \"title\""},
      {replaced("\"regions\": [\"pcf-filter\"]", "\"regions\": []"), "\"regions\" is empty"},
      {replaced("\"pixel\": 0.05", "\"pixle\": 0.05"), "unknown field \"pixle\""},
      {replaced("\"pixel\": 0.05", "\"pixel\": 2"), "tolerance \"pixel\" must be in"},
      {replaced("\"size\": \"64x32\"", "\"size\": \"64\""), "\"size\" must be WxH"},
      {replaced("\"name\": \"b\"", "\"name\": \"a\""), "two views named 'a'"},
      {replaced("\"name\": \"b\"", "\"name\": \"B b\""), "view name 'B b' must match"},
      {replaced("\"time_limit_s\": 12", "\"time_limit_s\": 0"), "\"time_limit_s\" must be in (0, 3600]"},
      {replaced("\"spp\": 16", "\"spp\": 0"), "\"spp\" must be a positive integer"},
  };
  for (const auto& [text, expect] : cases) {
    SCOPED_TRACE(expect);
    checkCaught(catchError([&] { parseExerciseDef(text, "demo.json"); }), ExitCode::Input, {"demo.json", expect});
  }
}

TEST(ExerciseDefinitions, UnknownExerciseIsUsageErrorWithSuggestion) {
  checkCaught(catchError([] { findExercise("pcff"); }), ExitCode::Usage, {"unknown exercise 'pcff'", "did you mean 'pcf'"});
}
