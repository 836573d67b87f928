// params/preset: loading (every malformed file is exit 3 naming the file), applying (an unknown
// key or bad value is exit 2 naming the key and the file), exact save/load round trips, and the
// precedence defaults < preset < --set.
#include "params/param_set.h"
#include "params/preset.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include "test_util.h"
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;
using namespace rtlab;
using rtlab::test::catchError;
using rtlab::test::Caught;
using nlohmann::json;

namespace {


fs::path freshDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  fs::path dir = fs::path(RTLAB_TEST_TMP) / "preset" /
                 (std::string(info->test_suite_name()) + "." + info->name() + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string writeFile(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  return path.string();
}

std::vector<ParamSpec> specs() {
  return {
      ParamSpec::real("t.f", "F", 0.5, -2.0, 3.0),
      ParamSpec::integer("t.i", "I", 4, -8, 16),
      ParamSpec::boolean("t.b", "B", false),
      ParamSpec::choice("t.e", "E", {"low", "mid", "high"}, 1),
      ParamSpec::vector3("t.v", "V", {0, 1, 0}, -10.0, 10.0),
      ParamSpec::color("t.c", "C", {1, 1, 1}),
  };
}

ParamSet makeSet() {
  ParamSet set;
  set.declare(specs());
  return set;
}

} // namespace

TEST(PresetLoad, ValidFileWithAllFields) {
  const fs::path dir = freshDir();
  const std::string path = writeFile(dir / "p.json", R"({
    "schema": 1,
    "scene": "contact",
    "techniques": ["pcss", "bloom"],
    "params": {"t.v": [1, 2, 3], "t.f": 1.5, "t.i": -3, "t.b": true, "t.e": "high", "t.c": [0.25, 0.5, 0]}
  })");
  const Preset p = loadPreset(path);
  ASSERT_TRUE(p.scene.has_value());
  EXPECT_EQ(*p.scene, "contact");
  ASSERT_TRUE(p.techniques.has_value());
  EXPECT_EQ(*p.techniques, (std::vector<std::string>{"pcss", "bloom"}));
  ASSERT_EQ(p.params.size(), 6u);
  EXPECT_EQ(p.params[0].first, "t.v"); // file order, not sorted
  EXPECT_EQ(p.params[1].first, "t.f");
  EXPECT_EQ(p.params[5].first, "t.c");

  ParamSet set = makeSet();
  applyPreset(p, set, path);
  EXPECT_EQ(set.getVec3("t.v"), glm::vec3(1, 2, 3));
  EXPECT_EQ(set.getFloat("t.f"), 1.5f);
  EXPECT_EQ(set.getInt("t.i"), -3);
  EXPECT_TRUE(set.getBool("t.b"));
  EXPECT_EQ(set.getEnumName("t.e"), "high");
  EXPECT_EQ(set.getVec3("t.c"), glm::vec3(0.25f, 0.5f, 0));
}

TEST(PresetLoad, EveryFieldOptional) {
  const fs::path dir = freshDir();
  const Preset p = loadPreset(writeFile(dir / "empty.json", "{}"));
  EXPECT_FALSE(p.scene.has_value());
  EXPECT_FALSE(p.techniques.has_value());
  EXPECT_TRUE(p.params.empty());
  const Preset q = loadPreset(writeFile(dir / "t.json", R"({"techniques": []})"));
  ASSERT_TRUE(q.techniques.has_value());
  EXPECT_TRUE(q.techniques->empty());
  ParamSet set = makeSet();
  const auto rev = set.revision();
  applyPreset(p, set, "empty.json");
  EXPECT_EQ(set.revision(), rev);
}

TEST(PresetLoad, MissingFileOrDirectoryIsInputError) {
  const fs::path dir = freshDir();
  const std::string missing = (dir / "missing.json").string();
  EXPECT_RTLAB_ERROR(loadPreset(missing), ExitCode::Input, missing);
  fs::create_directories(dir / "adir.json");
  const std::string adir = (dir / "adir.json").string();
  EXPECT_RTLAB_ERROR(loadPreset(adir), ExitCode::Input, adir);
}

TEST(PresetLoad, InvalidFilesAreInputErrorsNamingTheFile) {
  const fs::path dir = freshDir();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"empty", ""},
      {"notjson", "hello"},
      {"truncated", R"({"schema": 1, "params": {"t.f": 1)"},
      {"trailing", R"({"schema": 1} junk)"},
      {"array", "[1, 2, 3]"},
      {"string", "\"preset\""},
      {"schema2", R"({"schema": 2})"},
      {"schema0", R"({"schema": 0})"},
      {"schemastr", R"({"schema": "1"})"},
      {"schemafloat", R"({"schema": 1.5})"},
      {"schemawrap", R"({"schema": 4294967297})"},
      {"schemaneg", R"({"schema": -1})"},
      {"scenenum", R"({"scene": 5})"},
      {"scenenull", R"({"scene": null})"},
      {"techstr", R"({"techniques": "pcss"})"},
      {"technum", R"({"techniques": ["pcss", 1]})"},
      {"techobj", R"({"techniques": {"pcss": true}})"},
      {"paramsarray", R"({"params": [["t.f", 1]]})"},
      {"paramsstr", R"({"params": "t.f=1"})"},
      {"unknownfield", R"({"schema": 1, "param": {"t.f": 1}})"},
      {"unknownfield2", R"({"Scene": "contact"})"},
  };
  for (const auto& [name, text] : cases) {
    const std::string path = writeFile(dir / (name + ".json"), text);
    SCOPED_TRACE(name);
    EXPECT_RTLAB_ERROR(loadPreset(path), ExitCode::Input, path);
  }
}

TEST(PresetApply, UnknownKeyIsUsageNamingKeyAndFile) {
  const fs::path dir = freshDir();
  const std::string path = writeFile(dir / "p.json", R"({"params": {"t.f": 1.0, "t.flt": 2.0}})");
  const Preset p = loadPreset(path); // loading does not know the keys
  ParamSet set = makeSet();
  EXPECT_RTLAB_ERROR(applyPreset(p, set, path), ExitCode::Usage, "'t.flt'", path, "did you mean 't.f'");
}

TEST(PresetApply, BadValuesAreUsageNamingKeyRangeAndFile) {
  const fs::path dir = freshDir();
  struct Case {
    const char* text;
    const char* key;
    const char* range;
  };
  for (const Case& c : {Case{R"({"params": {"t.f": 3.5}})", "'t.f'", "[-2, 3]"},
                        Case{R"({"params": {"t.f": "1.5"}})", "'t.f'", "[-2, 3]"},
                        Case{R"({"params": {"t.i": 2.5}})", "'t.i'", "[-8, 16]"},
                        Case{R"({"params": {"t.b": "yes"}})", "'t.b'", "true|false"},
                        Case{R"({"params": {"t.e": "medium"}})", "'t.e'", "one of: low, mid, high"},
                        Case{R"({"params": {"t.e": 2}})", "'t.e'", "one of: low, mid, high"},
                        Case{R"({"params": {"t.v": [1, 2]}})", "'t.v'", "[-10, 10]"},
                        Case{R"({"params": {"t.c": [0, 0, 2]}})", "'t.c'", "[0, 1]"}}) {
    SCOPED_TRACE(c.text);
    const std::string path = writeFile(dir / "bad.json", c.text);
    const Preset p = loadPreset(path);
    ParamSet set = makeSet();
    EXPECT_RTLAB_ERROR(applyPreset(p, set, path), ExitCode::Usage, c.key, c.range, path);
  }
}

TEST(PresetRoundTrip, EveryValueOfEveryTypeExactly) {
  const fs::path dir = freshDir();
  std::vector<ParamSpec> list = specs();
  list.push_back(ParamSpec::real("t.tenth", "0.1", 0.5, 0.0, 1.0));
  list.push_back(ParamSpec::real("t.tiny", "1e-5", 0.5, 0.0, 1.0).logScale());
  list.push_back(ParamSpec::real("t.third", "1/3", 0.5, 0.0, 1.0));
  list.push_back(ParamSpec::real("t.big", "big", 0.5, -1e6, 1e6));
  list.push_back(ParamSpec::real("t.fromfloat", "float", 0.5, 0.0, 1.0));
  list.push_back(ParamSpec::boolean("t.b2", "B2", true));
  list.push_back(ParamSpec::choice("t.e2", "E2", {"16", "24", "32f"}, 1));
  list.push_back(ParamSpec::vector3("t.v2", "V2", {0, 0, 0}, -1e5, 1e5));

  ParamSet original;
  original.declare(list);
  original.setText("t.f", "-1.7");
  original.setText("t.i", "-7");
  original.setText("t.b", "true");
  original.setText("t.e", "high");
  original.setText("t.v", "0.1,-0.2,1e-5");
  original.setText("t.c", "0.1,0.2,0.3");
  original.setText("t.tenth", "0.1");
  original.setText("t.tiny", "1e-5");
  original.set("t.third", ParamValue::scalar(1.0 / 3.0));
  original.setText("t.big", "-123456.789012345");
  original.set("t.fromfloat", ParamValue::scalar(double(0.1f)));
  original.setText("t.b2", "off");
  original.setText("t.e2", "32f");
  original.set("t.v2", ParamValue::vec3({0.1f, -1.0f / 3.0f, 12345.678f}));

  const std::string path = (dir / "saved.json").string();
  savePreset(path, "cornell", {"pcss", "bloom"}, original);
  ASSERT_TRUE(fs::exists(path));
  for (const auto& e : fs::directory_iterator(dir)) EXPECT_EQ(e.path().filename(), "saved.json"); // no temporaries

  const Preset loaded = loadPreset(path);
  ASSERT_TRUE(loaded.scene.has_value());
  EXPECT_EQ(*loaded.scene, "cornell");
  ASSERT_TRUE(loaded.techniques.has_value());
  EXPECT_EQ(*loaded.techniques, (std::vector<std::string>{"pcss", "bloom"}));
  EXPECT_EQ(loaded.params.size(), list.size());

  ParamSet restored;
  restored.declare(list); // defaults
  applyPreset(loaded, restored, path);
  for (const auto& spec : list) {
    SCOPED_TRACE(spec.key);
    EXPECT_EQ(restored.value(spec.key).v, original.value(spec.key).v);
  }
  EXPECT_EQ(restored.getEnumName("t.e2"), "32f");
  EXPECT_FALSE(restored.getBool("t.b2"));
  EXPECT_EQ(restored.value("t.tenth").v[0], 0.1);
  EXPECT_EQ(restored.value("t.tiny").v[0], 1e-5);

  // The file is a contract preset: schema 1, enums as names, vec3 as arrays, ints as integers.
  std::ifstream in(path);
  const json j = json::parse(in);
  EXPECT_EQ(j["schema"], 1);
  EXPECT_EQ(j["params"]["t.e2"], "32f");
  EXPECT_TRUE(j["params"]["t.i"].is_number_integer());
  EXPECT_TRUE(j["params"]["t.b"].is_boolean());
  EXPECT_TRUE(j["params"]["t.v"].is_array());
}

TEST(PresetSave, UnwritablePathIsOutputError) {
  const fs::path dir = freshDir();
  const std::string path = (dir / "no_such_dir" / "p.json").string();
  ParamSet set = makeSet();
  EXPECT_RTLAB_ERROR(savePreset(path, "contact", {}, set), ExitCode::Output, path);
  EXPECT_FALSE(fs::exists(dir / "no_such_dir"));
}

TEST(PresetPrecedence, DefaultsThenPresetThenSet) {
  const fs::path dir = freshDir();
  const std::string path = writeFile(dir / "p.json", R"({"params": {"t.f": 1.0, "t.i": 2, "t.e": "low"}})");
  ParamSet set = makeSet();
  applyPreset(loadPreset(path), set, path); // --preset first
  set.setAssignment("t.f=2.5");             // then --set
  set.setAssignment("t.v=3,3,3");
  EXPECT_EQ(set.getFloat("t.f"), 2.5f);            // --set beats the preset
  EXPECT_EQ(set.getInt("t.i"), 2);                 // preset beats the default
  EXPECT_EQ(set.getEnumName("t.e"), "low");        // preset beats the default
  EXPECT_EQ(set.getVec3("t.v"), glm::vec3(3, 3, 3)); // --set beats the default
  EXPECT_FALSE(set.getBool("t.b"));                // untouched: default
  EXPECT_EQ(set.getVec3("t.c"), glm::vec3(1, 1, 1)); // untouched: default
}
