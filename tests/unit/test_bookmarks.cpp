// viewer/bookmarks: exact save/load round trips (floats written as their shortest decimals),
// atomic saving, and malformed files: exit 3 naming the file and the bookmark, exit 2 for a
// value out of range or choices.
#include "frame/registry.h"
#include "params/param_set.h"
#include "util/error.h"
#include "viewer/bookmarks.h"

#include <gtest/gtest.h>

#include "test_util.h"

#include <string>
#include <vector>

using namespace rtlab;
using nlohmann::json;
using rtlab::test::catchError;
using rtlab::test::Caught;
using rtlab::test::checkCaught;

namespace {

Bookmark full() {
  Bookmark b;
  b.name = "PCSS vs reference";
  b.scene = "contact";
  b.techniques = std::vector<std::string>{"pcss", "ssao"};
  b.params = {{"pcss.filter_samples", 32}, {"light0.color", {1.0, 0.5, 0.25}}, {"tonemap.operator", "aces"}};
  b.cameraPosition = glm::vec3(0.1f, 2.0f / 3.0f, -5.5f);
  b.cameraTarget = glm::vec3(0, 0.3f, 0);
  b.cameraFov = 37.5f;
  b.view = {{"aov", "visibility"}, {"mode", "pip"}, {"min", 0}, {"max", 0.5}, {"false_color", true}};
  b.compare = {{"mode", "reference"}, {"divider", 0.3}};
  b.notes = "Drag the divider across the penumbra.\nThen switch to pcf.";
  b.panel = false;
  b.sections = {{"Debug view", true}, {"Timings", false}};
  return b;
}

void expectSame(const Bookmark& a, const Bookmark& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.scene, b.scene);
  EXPECT_EQ(a.techniques, b.techniques);
  EXPECT_EQ(a.params, b.params);
  EXPECT_EQ(a.cameraPosition, b.cameraPosition); // exact: floats survive the decimal text
  EXPECT_EQ(a.cameraTarget, b.cameraTarget);
  EXPECT_EQ(a.cameraFov, b.cameraFov);
  EXPECT_EQ(a.view, b.view);
  EXPECT_EQ(a.compare, b.compare);
  EXPECT_EQ(a.notes, b.notes);
  EXPECT_EQ(a.panel, b.panel);
  EXPECT_EQ(a.sections, b.sections);
}

Caught parse(const std::string& text) {
  return catchError([&] { parseBookmarks(text, "talk.json"); });
}

// A file whose bookmark 1 is `second`.
Caught parseSecond(const std::string& second) {
  return parse(R"({"schema": 1, "bookmarks": [{"name": "first"}, )" + second + "]}");
}

} // namespace

TEST(Bookmarks, SaveLoadRoundTripIsExact) {
  const auto dir = rtlab::test::freshTestDir("bookmarks");
  Bookmark minimal;
  minimal.name = "just a name";
  const std::vector<Bookmark> saved = {full(), minimal};
  const std::string path = (dir / "talk.json").string();
  saveBookmarks(path, saved);
  EXPECT_EQ(rtlab::test::dirEntries(dir), std::set<std::string>{"talk.json"}) << "a temporary was left behind";
  const auto loaded = loadBookmarks(path);
  ASSERT_EQ(loaded.size(), 2u);
  expectSame(loaded[0], saved[0]);
  expectSame(loaded[1], saved[1]);
  // Saved again, the file is identical: nothing drifts through a load.
  const std::string text = rtlab::test::slurp(path);
  saveBookmarks(path, loaded);
  EXPECT_EQ(rtlab::test::slurp(path), text);
  // Floats are written as their shortest decimals, not as widened doubles.
  EXPECT_NE(text.find("0.1,"), std::string::npos) << text;
  EXPECT_EQ(text.find("0.10000000149"), std::string::npos) << text;
}

TEST(Bookmarks, ToJsonHoldsOnlyTheFieldsThatAreSet) {
  Bookmark b;
  b.name = "n";
  EXPECT_EQ(bookmarkToJson(b), json({{"name", "n"}}));
  b.cameraFov = 60.0f;
  EXPECT_EQ(bookmarkToJson(b), json({{"name", "n"}, {"camera", {{"fov", 60.0}}}}));
  const json j = bookmarkToJson(full());
  EXPECT_EQ(j["techniques"], json({"pcss", "ssao"}));
  EXPECT_EQ(j["camera"]["position"][0].get<double>(), 0.1);
  expectSame(parseBookmarks(json({{"bookmarks", {j}}}).dump(), "x")[0], full());
}

TEST(Bookmarks, MalformedFilesAreInputErrorsNamingTheFile) {
  checkCaught(parse("{\"bookmarks\": ["), ExitCode::Input, {"bookmarks 'talk.json'", "not valid JSON"});
  checkCaught(parse("[]"), ExitCode::Input, {"bookmarks 'talk.json'", "must be a JSON object"});
  checkCaught(parse("{\"schema\": 1}"), ExitCode::Input, {"talk.json", "missing field \"bookmarks\""});
  checkCaught(parse("{\"bookmarks\": {}}"), ExitCode::Input, {"talk.json", "\"bookmarks\" must be an array"});
  checkCaught(parse("{\"schema\": 2, \"bookmarks\": []}"), ExitCode::Input, {"talk.json", "unsupported schema 2"});
  checkCaught(parse("{\"bookmarks\": [], \"slides\": 3}"), ExitCode::Input, {"talk.json", "unknown field \"slides\""});
  EXPECT_TRUE(parseBookmarks("{\"bookmarks\": []}", "talk.json").empty());
}

TEST(Bookmarks, MalformedBookmarksNameTheirIndexAndName) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"("second")", "bookmark 1 must be a JSON object"},
      {R"({"scene": "contact"})", "bookmark 1: missing field \"name\""},
      {R"({"name": 2})", "bookmark 1: \"name\" must be a string"},
      {R"({"name": "b", "speaker": "x"})", "bookmark 1 ('b'): unknown field \"speaker\""},
      {R"({"name": "b", "notes": 3})", "bookmark 1 ('b'): \"notes\" must be a string"},
      {R"({"name": "b", "panel": "hide"})", "bookmark 1 ('b'): \"panel\" must be a boolean"},
      {R"({"name": "b", "sections": {"Timings": 1}})", "\"sections\": \"Timings\" must be a boolean"},
      {R"({"name": "b", "scene": 1})", "bookmark 1 ('b'): \"scene\" must be a string"},
      {R"({"name": "b", "techniques": "pcss"})", "bookmark 1 ('b'): \"techniques\" must be an array of strings"},
      {R"({"name": "b", "params": [1]})", "bookmark 1 ('b'): \"params\" must be a JSON object"},
      {R"({"name": "b", "params": {"pcss.filter_samples": {}}})", "value of 'pcss.filter_samples' must be a number"},
      {R"({"name": "b", "camera": {"position": [0, 1]}})", "\"position\" must be an array of 3 numbers"},
      {R"({"name": "b", "camera": {"up": [0, 1, 0]}})", "\"camera\": unknown field \"up\""},
      {R"({"name": "b", "view": {"aov": 3}})", "\"view\": \"aov\" must be a string"},
      {R"({"name": "b", "view": {"zoom": 2}})", "\"view\": unknown field \"zoom\""},
      {R"({"name": "b", "compare": "reference"})", "\"compare\" must be a JSON object"},
  };
  for (const auto& [bookmark, message] : cases)
    checkCaught(parseSecond(bookmark), ExitCode::Input, {"bookmarks 'talk.json'", message});
}

TEST(Bookmarks, ValuesOutOfRangeOrChoicesAreUsageErrors) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"name": ""})", "\"name\" must not be empty"},
      {R"({"name": "b", "camera": {"fov": 0.5}})", "\"fov\" = 0.5 is out of range [1, 170]"},
      {R"({"name": "b", "camera": {"position": [1, 2, 3], "target": [1, 2, 3]}})", "must differ"},
      {R"({"name": "b", "view": {"mode": "split"}})", "\"mode\" must be one of: full, pip, off"},
      {R"({"name": "b", "compare": {"divider": -0.1}})", "\"divider\" = -0.1 is out of range [0, 1]"},
      {R"({"name": "b", "sections": {"Timing": true}})", "unknown section \"Timing\""},
  };
  for (const auto& [bookmark, message] : cases)
    checkCaught(parseSecond(bookmark), ExitCode::Usage, {"bookmarks 'talk.json' bookmark 1", message});
}

TEST(Bookmarks, FileErrors) {
  const auto dir = rtlab::test::freshTestDir("bookmarks");
  checkCaught(catchError([&] { loadBookmarks((dir / "none.json").string()); }), ExitCode::Input,
              {"cannot read bookmarks", "none.json"});
  checkCaught(catchError([&] { loadBookmarks(dir.string()); }), ExitCode::Input, {"it is a directory"});
  const std::string nowhere = (dir / "missing_dir" / "talk.json").string();
  checkCaught(catchError([&] { saveBookmarks(nowhere, {full()}); }), ExitCode::Output, {"talk.json"});
  EXPECT_TRUE(rtlab::test::dirEntries(dir).empty());
}

namespace {

TechniqueRegistry bookmarkRegistry() {
  TechniqueRegistry r;
  TechniqueEntry e;
  e.info.id = "sh";
  e.info.stage = "shadow";
  e.info.title = "sh";
  e.info.params = {ParamSpec::integer("sh.samples", "Samples", 16, 1, 64)};
  e.info.debugViews = {{"sh.kernel", 1, ""}};
  e.create = [] { return std::unique_ptr<Technique>(); }; // never called
  r.add(e);
  return r;
}

ParamSet bookmarkParams(const TechniqueRegistry& r) {
  ParamSet p;
  p.declare(r.entries()[0].info.params);
  p.declare(ParamSpec::real("camera.fov", "Fov", 45, 1, 170));
  return p;
}

Caught validate(const std::string& bookmarks, const std::string& currentScene = "") {
  return catchError([&] {
    const TechniqueRegistry r = bookmarkRegistry();
    validateBookmarks(parseBookmarks("{\"bookmarks\": [{\"name\": \"ok\"}, " + bookmarks + "]}", "talk.json"),
                      bookmarkParams(r), r, "talk.json", currentScene);
  });
}

} // namespace

TEST(Bookmarks, ValidationChecksTechniquesKeysValuesAndAovs) {
  EXPECT_FALSE(validate(R"({"name": "b", "techniques": ["sh", "none"], "params": {"sh.samples": 64},
                            "view": {"aov": "sh.kernel"}})")
                   .thrown);
  checkCaught(validate(R"({"name": "b", "techniques": ["pcss"]})"), ExitCode::Usage,
              {"bookmarks 'talk.json' bookmark 1 ('b')", "unknown technique 'pcss'"});
  checkCaught(validate(R"({"name": "b", "params": {"sh.sample": 2}})"), ExitCode::Usage,
              {"bookmark 1 ('b')", "unknown key 'sh.sample'"});
  checkCaught(validate(R"({"name": "b", "params": {"sh.samples": 65}})"), ExitCode::Usage,
              {"bookmark 1 ('b')", "sh.samples"});
  checkCaught(validate(R"({"name": "b", "view": {"aov": "sh.blocker"}})"), ExitCode::Usage,
              {"bookmark 1 ('b')", "unknown AOV 'sh.blocker'"});
  // Keys of a bookmark for another scene are that scene's: checked when it is loaded.
  EXPECT_FALSE(validate(R"({"name": "b", "scene": "cornell", "params": {"light3.radius": 1}})").thrown);
  checkCaught(validate(R"({"name": "b", "scene": "cornell", "params": {"light3.radius": 1}})", "cornell"),
              ExitCode::Usage, {"bookmark 1 ('b')", "unknown key 'light3.radius'"});
}

// Speaker notes: exported as Markdown, a heading per bookmark in file order with its setup and
// notes; a bookmark without notes says so.
TEST(Bookmarks, NotesExportAsMarkdown) {
  Bookmark bare;
  bare.name = "Hard shadow";
  bare.techniques = std::vector<std::string>{"shadow_map"};
  const std::string md = bookmarkNotesMarkdown({full(), bare}, "/talks/shadows.json");
  EXPECT_EQ(md.rfind("# Speaker notes: shadows.json\n", 0), 0u) << md;
  const auto first = md.find("## 1. PCSS vs reference"), second = md.find("## 2. Hard shadow");
  ASSERT_NE(first, std::string::npos) << md;
  ASSERT_NE(second, std::string::npos) << md;
  EXPECT_LT(first, second);
  EXPECT_NE(md.find("Drag the divider across the penumbra.\nThen switch to pcf."), std::string::npos) << md;
  EXPECT_NE(md.find("scene `contact`; techniques `pcss`, `ssao`; compare reference; view `visibility` (pip)"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("(no notes)", second), std::string::npos) << md;
}
