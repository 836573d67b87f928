// viewer/script: every action parses; malformed input (JSON, shape, unknown action or field,
// wrong JSON type) is exit 3 naming the script and the action index; values out of range or
// choices are exit 2; validation against a registry and parameters (unknown technique, stage,
// key, AOV, out-of-range value, preset files, output paths) is exit 2, 3 or 6 naming the action.
#include "frame/registry.h"
#include "params/param_set.h"
#include "params/preset.h"
#include "util/error.h"
#include "viewer/script.h"

#include <gtest/gtest.h>

#include "fake_technique.h"
#include "test_util.h"

#include <string>
#include <vector>

using namespace rtlab;
using nlohmann::json;
using rtlab::test::catchError;
using rtlab::test::Caught;
using rtlab::test::checkCaught;

namespace {

// Parses a one-action script and returns what it threw.
Caught parseOne(const std::string& action) {
  return catchError([&] { parseScript("[" + action + "]", "demo.json"); });
}

// Parses `[{"action":"snapshot"}, <action>]` so the action under test has index 1.
Caught parseSecond(const std::string& action) {
  return catchError([&] { parseScript("[{\"action\": \"snapshot\"}, " + action + "]", "demo.json"); });
}

using rtlab::test::fakeTechnique;

TechniqueRegistry scriptRegistry() {
  TechniqueRegistry r;
  r.add(
      fakeTechnique("sh", "shadow", {ParamSpec::integer("sh.samples", "Samples", 16, 1, 64)}, {{"sh.kernel", 1, ""}}));
  r.add(fakeTechnique("occ", "ao", {ParamSpec::real("occ.radius", "Radius", 0.5, 0.0, 2.0)}));
  return r;
}

ParamSet params(const TechniqueRegistry& r) {
  ParamSet p;
  for (const auto& e : r.entries())
    p.declare(e.info.params);
  p.declare(ParamSpec::vector3("camera.position", "Position", {0, 1, 5}, -1e4, 1e4));
  p.declare(ParamSpec::vector3("camera.target", "Target", {0, 0, 0}, -1e4, 1e4));
  p.declare(ParamSpec::real("camera.fov", "Fov", 45, 1, 170));
  return p;
}

Caught validate(const std::string& text) {
  return catchError([&] {
    const TechniqueRegistry r = scriptRegistry();
    validateScript(parseScript(text, "demo.json"), params(r), r);
  });
}

} // namespace

TEST(ViewerScript, ParsesEveryAction) {
  const std::string text = R"([
    {"action": "technique", "stage": "shadow", "id": "sh"},
    {"action": "set", "key": "sh.samples", "value": 32},
    {"action": "reset", "key": "sh.samples"},
    {"action": "camera", "position": [1, 2, 3], "target": [0, 0, 0], "fov": 40},
    {"action": "orbit", "yaw": 10, "pitch": -5},
    {"action": "view", "aov": "visibility", "mode": "pip", "min": 0, "max": 1, "false_color": true},
    {"action": "compare", "mode": "reference", "divider": 0.25},
    {"action": "snapshot"},
    {"action": "wait", "frames": 5},
    {"action": "wait_samples", "samples": 64, "timeout_s": 120},
    {"action": "screenshot", "file": "a.PNG"},
    {"action": "save_preset", "file": "p.json"},
    {"action": "load_preset", "file": "p.json"},
    {"action": "report", "file": "r.json"},
    {"action": "render_scale", "value": 0.5},
    {"action": "lecture", "on": true},
    {"action": "bookmark", "index": 0},
    {"action": "panel", "on": false},
    {"action": "section", "name": "Debug view", "open": true},
    {"action": "ramp", "key": "sh.samples", "from": 1, "to": 64, "frames": 30},
    {"action": "record", "dir": "frames"},
    {"action": "stop"},
    {"action": "quit"}
  ])";
  const auto script = parseScript(text, "demo.json");
  ASSERT_EQ(script.size(), scriptActionNames().size());
  for (std::size_t i = 0; i < script.size(); ++i) {
    EXPECT_EQ(script[i].action, scriptActionNames()[i]);
    EXPECT_EQ(script[i].index, i);
    EXPECT_EQ(script[i].source, "demo.json");
  }
  EXPECT_EQ(script[1].args["value"], 32);
  EXPECT_EQ(script[5].args["aov"], "visibility");
  EXPECT_EQ(script[8].where(), "script 'demo.json' action 8 (\"wait\")");
  EXPECT_TRUE(parseScript("[]", "empty.json").empty());
}

TEST(ViewerScript, MalformedDocumentsAreInputErrors) {
  checkCaught(catchError([] { parseScript("[{\"action\": ", "demo.json"); }), ExitCode::Input,
              {"script 'demo.json'", "not valid JSON", "line 1"});
  checkCaught(catchError([] { parseScript("[{\"action\": \"wait\", \"frames\": 1e400}]", "demo.json"); }),
              ExitCode::Input, {"script 'demo.json'", "not valid JSON", "overflow"});
  checkCaught(catchError([] { parseScript("{\"action\": \"quit\"}", "demo.json"); }), ExitCode::Input,
              {"script 'demo.json'", "JSON list of actions"});
  checkCaught(parseSecond("42"), ExitCode::Input, {"action 1", "must be a JSON object"});
  checkCaught(parseSecond("{\"frames\": 3}"), ExitCode::Input, {"action 1", "missing field \"action\""});
  checkCaught(parseSecond("{\"action\": 7}"), ExitCode::Input, {"action 1", "\"action\" must be a string"});
}

TEST(ViewerScript, UnknownActionIsAnInputErrorListingTheActions) {
  checkCaught(parseSecond("{\"action\": \"jump\"}"), ExitCode::Input,
              {"script 'demo.json' action 1", "unknown action \"jump\"", "wait_samples", "quit"});
}

TEST(ViewerScript, UnknownFieldIsAnInputError) {
  checkCaught(parseSecond("{\"action\": \"wait\", \"frame\": 5}"), ExitCode::Input,
              {"action 1 (\"wait\")", "unknown field \"frame\"", "frames"});
  checkCaught(parseOne("{\"action\": \"quit\", \"now\": true}"), ExitCode::Input,
              {"action 0 (\"quit\")", "unknown field \"now\"", "takes no fields"});
}

TEST(ViewerScript, MissingRequiredFieldsAreInputErrors) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"action": "technique", "id": "sh"})", "stage"},
      {R"({"action": "technique", "stage": "shadow"})", "id"},
      {R"({"action": "set", "value": 1})", "key"},
      {R"({"action": "set", "key": "sh.samples"})", "value"},
      {R"({"action": "reset"})", "key"},
      {R"({"action": "wait"})", "frames"},
      {R"({"action": "wait_samples", "timeout_s": 5})", "samples"},
      {R"({"action": "screenshot"})", "file"},
      {R"({"action": "save_preset"})", "file"},
      {R"({"action": "load_preset"})", "file"},
      {R"({"action": "report"})", "file"},
      {R"({"action": "render_scale"})", "value"},
      {R"({"action": "lecture"})", "on"},
      {R"({"action": "bookmark"})", "index"},
  };
  for (const auto& [action, field] : cases)
    checkCaught(parseSecond(action), ExitCode::Input, {"action 1", "missing field \"" + field + "\""});
}

TEST(ViewerScript, ActionsNeedAtLeastOneOfTheirOptionalFields) {
  for (const char* name : {"camera", "orbit", "view", "compare"})
    checkCaught(parseOne(std::string("{\"action\": \"") + name + "\"}"), ExitCode::Input,
                {std::string("(\"") + name + "\")", "needs at least one of"});
}

TEST(ViewerScript, WrongJsonTypesAreInputErrors) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"action": "wait", "frames": "5"})", "\"frames\" must be an integer"},
      {R"({"action": "wait", "frames": 2.5})", "\"frames\" must be an integer"},
      {R"({"action": "technique", "stage": "shadow", "id": 3})", "\"id\" must be a string"},
      {R"({"action": "camera", "position": [1, 2]})", "\"position\" must be an array of 3 numbers"},
      {R"({"action": "camera", "target": [1, "2", 3]})", "\"target\" must be an array of 3 numbers"},
      {R"({"action": "camera", "fov": "wide"})", "\"fov\" must be a number"},
      {R"({"action": "orbit", "yaw": "10"})", "\"yaw\" must be a number"},
      {R"({"action": "view", "false_color": 1})", "\"false_color\" must be a boolean"},
      {R"({"action": "compare", "divider": [0.5]})", "\"divider\" must be a number"},
      {R"({"action": "lecture", "on": "yes"})", "\"on\" must be a boolean"},
      {R"({"action": "set", "key": "sh.samples", "value": {"x": 1}})",
       "\"value\" must be a number, boolean, string or array"},
      {R"({"action": "set", "key": "sh.samples", "value": null})",
       "\"value\" must be a number, boolean, string or array"},
      {R"({"action": "screenshot", "file": ["a.png"]})", "\"file\" must be a string"},
  };
  for (const auto& [action, message] : cases)
    checkCaught(parseSecond(action), ExitCode::Input, {"action 1", message});
}

TEST(ViewerScript, LongValuesAreCutInMessages) {
  const Caught c = parseOne(R"({"action": "wait", "frames": ")" + std::string(500, 'x') + "\"}");
  checkCaught(c, ExitCode::Input, {"\"frames\" must be an integer, got \"xxxx"});
  EXPECT_LT(c.message.size(), 150u) << c.message;
  EXPECT_EQ(c.message.substr(c.message.size() - 3), "...");
}

TEST(ViewerScript, ValuesOutOfRangeOrChoicesAreUsageErrors) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"action": "wait", "frames": -1})", "\"frames\" must be >= 0"},
      {R"({"action": "wait_samples", "samples": -64})", "\"samples\" must be >= 0"},
      {R"({"action": "wait_samples", "samples": 64, "timeout_s": 0})", "\"timeout_s\" must be > 0"},
      {R"({"action": "bookmark", "index": -2})", "\"index\" must be >= 0"},
      {R"({"action": "render_scale", "value": 0})", "\"value\" = 0 is out of range [0.1, 1]"},
      {R"({"action": "render_scale", "value": 1.5})", "out of range"},
      {R"({"action": "compare", "divider": 1.5})", "\"divider\" = 1.5 is out of range [0, 1]"},
      {R"({"action": "compare", "mode": "ab"})", "\"mode\" must be one of: reference, snapshot, difference, off"},
      {R"({"action": "view", "mode": "side"})", "\"mode\" must be one of: full, pip, off"},
      {R"({"action": "view", "min": 1, "max": 1})", "\"min\" (1) must be less than \"max\" (1)"},
      {R"({"action": "camera", "position": [1, 1, 1], "target": [1, 1, 1]})",
       "\"target\" must differ from \"position\""},
      {R"({"action": "screenshot", "file": "shot.jpg"})", "must be a .png file"},
      {R"({"action": "camera", "target": [1e300, 0, 0]})", "\"target\" component 1e+300 is out of range"},
      {R"({"action": "report", "file": ""})", "\"file\" must not be empty"},
  };
  for (const auto& [action, message] : cases)
    checkCaught(parseSecond(action), ExitCode::Usage, {"action 1", message});
}

TEST(ViewerScript, LoadScriptNamesTheFile) {
  const auto dir = rtlab::test::freshTestDir("viewer_script");
  checkCaught(catchError([&] { loadScript((dir / "missing.json").string()); }), ExitCode::Input,
              {"cannot read script", "missing.json"});
  checkCaught(catchError([&] { loadScript(dir.string()); }), ExitCode::Input, {"it is a directory"});
  const std::string path = (dir / "bad.json").string();
  { std::ofstream(path) << R"([{"action": "wait", "frames": 1}, {"action": "wait", "frame": 1}])"; }
  checkCaught(catchError([&] { loadScript(path); }), ExitCode::Input, {"script '" + path + "' action 1", "\"frame\""});
  { std::ofstream(path) << R"([{"action": "quit"}])"; }
  EXPECT_EQ(loadScript(path).size(), 1u);
}

TEST(ViewerScript, ValidScriptValidates) {
  const auto c = validate(R"([
    {"action": "technique", "stage": "shadow", "id": "sh"},
    {"action": "technique", "stage": "ao", "id": "off"},
    {"action": "set", "key": "sh.samples", "value": 64},
    {"action": "set", "key": "occ.radius", "value": 2},
    {"action": "reset", "key": "sh.samples"},
    {"action": "camera", "position": [1, 2, 3], "fov": 170},
    {"action": "view", "aov": "sh.kernel"},
    {"action": "view", "aov": "ao"}
  ])");
  EXPECT_FALSE(c.thrown) << c.message;
}

TEST(ViewerScript, ValidationNamesTheActionForUnknownTechniquesAndStages) {
  checkCaught(
      validate(R"([{"action": "wait", "frames": 1}, {"action": "technique", "stage": "shadow", "id": "pcss2"}])"),
      ExitCode::Usage, {"script 'demo.json' action 1 (\"technique\")", "unknown technique 'pcss2'"});
  checkCaught(validate(R"([{"action": "technique", "stage": "shade", "id": "sh"}])"), ExitCode::Usage,
              {"action 0", "unknown stage 'shade'", "shadow"});
  checkCaught(validate(R"([{"action": "technique", "stage": "ao", "id": "sh"}])"), ExitCode::Usage,
              {"action 0", "technique 'sh' belongs to stage 'shadow', not 'ao'"});
}

TEST(ViewerScript, ValidationNamesTheActionForUnknownKeysAndBadValues) {
  checkCaught(validate(R"([{"action": "wait", "frames": 1}, {"action": "set", "key": "sh.sample", "value": 3}])"),
              ExitCode::Usage, {"action 1 (\"set\")", "unknown key 'sh.sample'", "did you mean 'sh.samples'"});
  checkCaught(validate(R"([{"action": "set", "key": "sh.samples", "value": 65}])"), ExitCode::Usage,
              {"action 0 (\"set\")", "sh.samples"});
  checkCaught(validate(R"([{"action": "set", "key": "sh.samples", "value": "many"}])"), ExitCode::Usage,
              {"action 0", "sh.samples"});
  checkCaught(validate(R"([{"action": "quit"}, {"action": "quit"}, {"action": "reset", "key": "nope.x"}])"),
              ExitCode::Usage, {"action 2 (\"reset\")", "unknown key 'nope.x'"});
  checkCaught(validate(R"([{"action": "camera", "fov": 171}])"), ExitCode::Usage,
              {"action 0 (\"camera\")", "camera.fov"});
  checkCaught(validate(R"([{"action": "view", "aov": "sh.blocker"}])"), ExitCode::Usage,
              {"action 0 (\"view\")", "unknown AOV 'sh.blocker'"});
}

TEST(ViewerScript, ValidationWorksOnACopyOfTheParameters) {
  const TechniqueRegistry r = scriptRegistry();
  const ParamSet p = params(r);
  validateScript(parseScript(R"([{"action": "set", "key": "sh.samples", "value": 2}])", "demo.json"), p, r);
  EXPECT_EQ(p.getInt("sh.samples"), 16);
}

TEST(ViewerScript, ValidationChecksPresetFilesAndOutputPaths) {
  const auto dir = rtlab::test::freshTestDir("viewer_script");
  const std::string missing = (dir / "missing.json").string();
  checkCaught(validate(R"([{"action": "quit"}, {"action": "load_preset", "file": ")" + missing + "\"}]"),
              ExitCode::Input, {"action 1 (\"load_preset\")", "missing.json"});
  // A preset the script saves first is not read before it exists.
  EXPECT_FALSE(validate(R"([{"action": "save_preset", "file": ")" + missing +
                        R"("}, {"action": "load_preset", "file": ")" + missing + "\"}]")
                   .thrown);
  const std::string bad = (dir / "bad.json").string();
  { std::ofstream(bad) << R"({"schema": 1, "params": {"sh.samples": 1000}})"; }
  checkCaught(validate(R"([{"action": "load_preset", "file": ")" + bad + "\"}]"), ExitCode::Usage,
              {"action 0 (\"load_preset\")", "sh.samples", "bad.json"});
  const std::string nowhere = (dir / "no_such_dir" / "shot.png").string();
  checkCaught(validate(R"([{"action": "screenshot", "file": ")" + nowhere + "\"}]"), ExitCode::Output,
              {"action 0 (\"screenshot\")", "no_such_dir"});
  EXPECT_TRUE(rtlab::test::dirEntries(dir).count("bad.json"));
  EXPECT_EQ(rtlab::test::dirEntries(dir).size(), 1u) << "validation wrote a file";
}

TEST(ViewerScript, BookmarkIndicesAreCheckedAgainstTheBookmarks) {
  const auto script =
      parseScript(R"([{"action": "bookmark", "index": 0}, {"action": "bookmark", "index": 2}])", "demo.json");
  validateScriptBookmarks(script, 3);
  checkCaught(catchError([&] { validateScriptBookmarks(script, 2); }), ExitCode::Usage,
              {"action 1 (\"bookmark\")", "bookmark 2 does not exist", "there are 2"});
  checkCaught(catchError([&] { validateScriptBookmarks(script, 0); }), ExitCode::Usage,
              {"action 0", "no bookmarks were loaded"});
}

TEST(ViewerScript, ActionsBuiltInCodeAreCheckedToo) {
  ScriptAction a;
  a.action = "set";
  a.index = 4;
  a.source = "viewer";
  a.args = {{"key", "sh.samples"}}; // no "value"
  checkCaught(catchError([&] { checkScriptAction(a); }), ExitCode::Input,
              {"script 'viewer' action 4 (\"set\")", "\"value\""});
  const TechniqueRegistry r = scriptRegistry();
  checkCaught(catchError([&] { validateScript({a}, params(r), r); }), ExitCode::Input, {"missing field \"value\""});
  a.args["value"] = 8;
  EXPECT_FALSE(catchError([&] { validateScript({a}, params(r), r); }).thrown);
  a.action = "teleport";
  checkCaught(catchError([&] { checkScriptAction(a); }), ExitCode::Input, {"action 4", "unknown action \"teleport\""});
}

TEST(ViewerScript, TheReferenceDocumentsEveryAction) {
  const std::string doc = rtlab::test::slurp(std::string(RTLAB_SOURCE_DIR) + "/docs/viewer-scripts.md");
  ASSERT_FALSE(doc.empty());
  for (const auto& name : scriptActionNames())
    EXPECT_NE(doc.find("| `" + name + "` |"), std::string::npos) << "docs/viewer-scripts.md has no row for " << name;
}

// "none" is how `-t none` and 'rtlab list' name "no technique"; the script's technique action
// takes it for one stage, as it takes "off".
TEST(ViewerScript, TechniqueNoneTurnsAStageOff) {
  const auto c = validate(R"([{"action": "technique", "stage": "shadow", "id": "none"}])");
  EXPECT_FALSE(c.thrown) << c.message;
}

TEST(ViewerScript, LecturerActionsCheckTheirFields) {
  checkCaught(parseOne(R"({"action": "panel"})"), ExitCode::Input, {"\"on\""});
  checkCaught(parseOne(R"({"action": "panel", "on": 1})"), ExitCode::Input, {"\"on\""});
  checkCaught(parseOne(R"({"action": "section", "name": "Debug"})"), ExitCode::Usage,
              {"action 0 (\"section\")", "unknown section \"Debug\"", "\"Debug view\""});
  checkCaught(parseOne(R"({"action": "section", "name": "Timings", "open": "yes"})"), ExitCode::Input, {"\"open\""});
  checkCaught(parseOne(R"({"action": "ramp", "key": "sh.samples", "from": 1, "to": 2})"), ExitCode::Input,
              {"\"frames\""});
  checkCaught(parseOne(R"({"action": "ramp", "key": "sh.samples", "from": 1, "to": 2, "frames": 0})"),
              ExitCode::Usage, {"\"frames\" must be >= 1"});
  checkCaught(parseOne(R"({"action": "ramp", "key": "sh.samples", "from": 1, "to": 2, "frames": 2.5})"),
              ExitCode::Input, {"\"frames\""});
  checkCaught(parseOne(R"({"action": "record", "dir": ""})"), ExitCode::Usage, {"\"dir\" must not be empty"});
  checkCaught(parseOne(R"({"action": "stop", "dir": "x"})"), ExitCode::Input, {"\"dir\""});
}

TEST(ViewerScript, RampsAreValidatedAgainstTheKey) {
  EXPECT_FALSE(validate(R"([{"action": "ramp", "key": "occ.radius", "from": 0, "to": 2, "frames": 10}])").thrown);
  checkCaught(validate(R"([{"action": "ramp", "key": "occ.radiu", "from": 0, "to": 2, "frames": 10}])"),
              ExitCode::Usage, {"action 0 (\"ramp\")", "unknown key 'occ.radiu'"});
  checkCaught(validate(R"([{"action": "ramp", "key": "occ.radius", "from": 0, "to": 3, "frames": 10}])"),
              ExitCode::Usage, {"action 0 (\"ramp\")", "occ.radius"});
  checkCaught(validate(R"([{"action": "ramp", "key": "camera.position", "from": 0, "to": 1, "frames": 2}])"),
              ExitCode::Usage, {"action 0 (\"ramp\")", "needs a float or int key"});
  // The ramp ends at its end value: a later "set" is checked against what the ramp left.
  EXPECT_FALSE(validate(R"([{"action": "ramp", "key": "sh.samples", "from": 1, "to": 64, "frames": 3},
                            {"action": "reset", "key": "sh.samples"}])")
                   .thrown);
}

TEST(ViewerScript, RecordNeedsAWritableDirectoryAndStopARecording) {
  const auto dir = rtlab::test::freshTestDir("viewer_script");
  const std::string ok = dir.string(), missing = (dir / "missing").string();
  EXPECT_FALSE(validate(R"([{"action": "record", "dir": ")" + ok + R"("}, {"action": "stop"}])").thrown);
  EXPECT_FALSE(validate(R"([{"action": "record", "dir": ")" + ok + R"("}])").thrown) << "ends with the window";
  checkCaught(validate(R"([{"action": "record", "dir": ")" + missing + R"("}])"), ExitCode::Output,
              {"action 0 (\"record\")", "missing", "does not exist"});
  checkCaught(validate(R"([{"action": "stop"}])"), ExitCode::Usage, {"action 0 (\"stop\")", "no recording"});
  checkCaught(validate(R"([{"action": "record", "dir": ")" + ok + R"("}, {"action": "record", "dir": ")" + ok +
                       R"("}])"),
              ExitCode::Usage, {"action 1 (\"record\")", "already running"});
  EXPECT_EQ(recordedFramePath("out", 12), (std::filesystem::path("out") / "frame_00012.png").string());
  EXPECT_TRUE(rtlab::test::dirEntries(dir).empty()) << "validation wrote a file";
}
