// rtlab exercise through the binary (docs/exercises.md, docs/contract.md "Exercises"): for every
// exercise, the untouched student folder fails with a low score and the "stub" cause, the shipped
// solution copied into it scores 100, and each deliberate mistake of tests/exercises/mutations.json
// fails (these grades share a grade cache: the solution and the stubs render once per build;
// test_exercise_cache.cpp checks that a cached grade equals a fresh one). Then the safety rules: an endless loop times out and grading completes, a syntax error is
// exit 5 naming the student's file:line, `new` never overwrites, a folder that is not an exercise is
// exit 3, nothing is written outside the output folder, and the grade is the same on EGL and OSMesa.
#include "chromium.h"
#include "exercise_helpers.h"
#include "process.h"
#include "test_util.h"

#include "image/image.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using nlohmann::json;
using namespace rtlab::test;

namespace {

std::vector<std::string> exerciseIds() {
  std::vector<std::string> ids;
  for (const auto& e : fs::directory_iterator(kSource / "assets" / "exercises"))
    if (e.path().extension() == ".json") ids.push_back(e.path().stem().string());
  std::sort(ids.begin(), ids.end());
  return ids;
}

class EveryExercise : public ::testing::TestWithParam<std::string> {};

} // namespace

TEST(ExerciseCli, ListNamesAnExerciseForEveryTechnique) {
  const auto list = runProcess(RTLAB_BINARY, {"exercise", "list", "--json"});
  ASSERT_EQ(list.exitCode, 0) << list.err;
  const json j = json::parse(list.out);
  EXPECT_EQ(j["schema"], 1);
  const auto techniques = runProcess(RTLAB_BINARY, {"list", "--json"});
  ASSERT_EQ(techniques.exitCode, 0);
  std::set<std::string> withExercise;
  for (const auto& e : j["exercises"]) {
    withExercise.insert(e["technique"].get<std::string>());
    EXPECT_FALSE(e["title"].get<std::string>().empty());
    for (const auto& f : e["files"]) EXPECT_TRUE(fs::is_regular_file(kSource / f.get<std::string>())) << f;
  }
  for (const auto& t : json::parse(techniques.out)["techniques"]) {
    const std::string id = t["id"].get<std::string>();
    EXPECT_TRUE(withExercise.count(id)) << "no exercise for technique " << id;
  }
}

TEST_P(EveryExercise, NewFolderIsStubbedAndItsUntouchedGradeIsLowWithTheStubCause) {
  const std::string id = GetParam();
  const fs::path dir = freshTestDir("exercise");
  const fs::path folder = newFolder(id, dir);
  const json manifest = json::parse(slurp(folder / "exercise.json"));
  EXPECT_EQ(manifest["schema"], 1);
  EXPECT_EQ(manifest["exercise"], id);
  const std::string readme = slurp(folder / "README.md");
  EXPECT_NE(readme.find("rtlab view --exercise ."), std::string::npos);
  for (const auto& f : folderFiles(folder)) {
    const std::string copy = slurp(folder / f);
    EXPECT_NE(copy.find("// Stub:"), std::string::npos) << f;
    EXPECT_NE(copy, slurp(kSource / f)) << f;
  }
  const Grade g = grade(folder, sharedGradeCache());
  ASSERT_EQ(g.process.exitCode, 0) << describe(g);
  EXPECT_EQ(g.result["exercise"], id);
  EXPECT_FALSE(g.result["passed"].get<bool>());
  EXPECT_LE(g.result["score"].get<int>(), 25) << describe(g);
  int stubCauses = 0;
  for (const auto& v : g.result["views"]) {
    if (v["passed"].get<bool>()) continue;
    EXPECT_EQ(v["status"], "failed") << v.dump();
    stubCauses += v["cause"].get<std::string>().rfind("stub:", 0) == 0 ? 1 : 0;
  }
  EXPECT_GE(stubCauses, 1) << describe(g);
}

TEST_P(EveryExercise, ShippedSolutionScores100) {
  const std::string id = GetParam();
  const fs::path folder = newFolder(id, freshTestDir("exercise"));
  copySolution(folder);
  const Grade g = grade(folder, sharedGradeCache());
  ASSERT_EQ(g.process.exitCode, 0) << describe(g);
  EXPECT_EQ(g.result["score"], 100) << describe(g);
  EXPECT_TRUE(g.result["passed"].get<bool>());
  for (const auto& v : g.result["views"]) {
    EXPECT_EQ(v["status"], "passed");
    EXPECT_EQ(v["cause"], "");
    EXPECT_EQ(v["rmse_vs_solution"].get<double>(), 0.0) << v.dump();
    EXPECT_DOUBLE_EQ(v["rmse_vs_reference"].get<double>(), v["solution_rmse_vs_reference"].get<double>());
    EXPECT_GT(v["ms"].get<double>(), 0.0);
  }
}

TEST_P(EveryExercise, EachDeliberateMistakeFails) {
  const std::string id = GetParam();
  const json mutations = json::parse(slurp(kSource / "tests" / "exercises" / "mutations.json"))["mutations"];
  const fs::path folder = newFolder(id, freshTestDir("exercise"));
  int tried = 0;
  for (const auto& m : mutations) {
    if (m["exercise"] != id) continue;
    SCOPED_TRACE(m["why"].get<std::string>());
    copySolution(folder);
    const std::string file = m["file"].get<std::string>();
    std::string text = slurp(folder / file);
    const std::string find = m["find"].get<std::string>();
    const auto at = text.find(find);
    ASSERT_NE(at, std::string::npos) << find;
    ASSERT_EQ(text.find(find, at + 1), std::string::npos) << "not unique: " << find;
    writeText(folder / file, text.replace(at, find.size(), m["replace"].get<std::string>()));
    const Grade g = grade(folder, sharedGradeCache());
    ASSERT_EQ(g.process.exitCode, 0) << describe(g);
    EXPECT_LT(g.result["score"].get<int>(), 100) << describe(g);
    EXPECT_FALSE(g.result["passed"].get<bool>());
    ++tried;
  }
  EXPECT_GE(tried, 1) << "no mutation of exercise " << id << " in tests/exercises/mutations.json";
}

INSTANTIATE_TEST_SUITE_P(Exercises, EveryExercise, ::testing::ValuesIn(exerciseIds()),
                         [](const auto& info) { return info.param; });

// An endless loop: each view is killed at the time limit, the next starts in a new process, and
// grading completes with every view a timeout. (llvmpipe ends any one loop after 65535 iterations,
// so the loop body is made long enough that the render still never finishes.)
TEST(ExerciseCli, EndlessLoopTimesOutAndGradingCompletes) {
  const fs::path dir = freshTestDir("exercise");
  const fs::path folder = newFolder("pcf", dir);
  copySolution(folder);
  const std::string file = "shaders/shadow/common/shadow_filter.glsl";
  std::string text = slurp(folder / file);
  const auto at = text.rfind("  return lit / float(tapCount);");
  ASSERT_NE(at, std::string::npos);
  std::string loop = "  for (int k = 0; k >= 0; ++k) {\n";
  for (int i = 0; i < 256; ++i)
    loop += "    lit += texture(uShadowMap, vec3(coord.xy + vec2(float(k) * 1e-7, " + std::to_string(i) + ".0e-6), coord.z));\n";
  loop += "  }\n";
  writeText(folder / file, text.insert(at, loop));
  const auto start = std::chrono::steady_clock::now();
  const Grade g = grade(folder, {"--views", firstViews("pcf", 2, dir).string(), "--time-limit", "3"});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(g.process.exitCode, 0) << describe(g);
  ASSERT_EQ(g.result["views"].size(), 2u);
  for (const auto& v : g.result["views"]) {
    EXPECT_EQ(v["status"], "timeout") << v.dump();
    EXPECT_EQ(v["cause"].get<std::string>().rfind("timeout:", 0), 0u);
    EXPECT_FALSE(v["passed"].get<bool>());
  }
  EXPECT_EQ(g.result["score"], 0);
  EXPECT_LT(seconds, 90.0) << "two 3 s limits plus the solution's renders";
}

TEST(ExerciseCli, SyntaxErrorIsExit5NamingTheStudentsFileAndLineWithTheJsonWritten) {
  const fs::path dir = freshTestDir("exercise");
  const fs::path folder = newFolder("shadow_map", dir);
  const std::string file = folderFiles(folder).front();
  std::string text = slurp(folder / file);
  const auto at = text.find("// Stub:");
  ASSERT_NE(at, std::string::npos);
  text.insert(at, "this is not GLSL;\n");
  writeText(folder / file, text);
  const int line = int(std::count(text.begin(), text.begin() + long(at), '\n')) + 1;
  const Grade g = grade(folder, {"--views", firstViews("shadow_map", 2, dir).string()});
  EXPECT_EQ(g.process.exitCode, 5) << describe(g);
  EXPECT_NE(g.process.err.find("rtlab: error: "), std::string::npos) << g.process.err;
  EXPECT_NE(g.process.err.find((folder / file).string() + ":" + std::to_string(line) + ":"), std::string::npos)
      << g.process.err << " (expected line " << line << ")";
  ASSERT_TRUE(g.result.is_object()) << "the JSON is written on a compile error: " << g.process.out;
  EXPECT_EQ(g.result["score"], 0);
  for (const auto& v : g.result["views"]) EXPECT_EQ(v["status"], "compile_error");
  // render --exercise reports the same error, exit 5.
  const auto r = runProcess(RTLAB_BINARY, {"render", "--exercise", folder.string(), "--size", "32x18", "--aov", "visibility",
                                           "--out", (dir / "x.exr").string()});
  EXPECT_EQ(r.exitCode, 5) << r.err;
  EXPECT_NE(r.err.find((folder / file).string() + ":" + std::to_string(line) + ":"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.exr"));
}

TEST(ExerciseCli, NewRefusesANonEmptyFolderAndChangesNothing) {
  const fs::path dir = freshTestDir("exercise");
  const fs::path folder = dir / "taken";
  fs::create_directories(folder);
  writeText(folder / "notes.txt", "mine");
  const auto r = runProcess(RTLAB_BINARY, {"exercise", "new", "pcss", "--out", folder.string()});
  EXPECT_EQ(r.exitCode, 6) << r.err;
  EXPECT_NE(r.err.find("not empty"), std::string::npos) << r.err;
  EXPECT_EQ(rtlab::test::dirEntries(folder), std::set<std::string>{"notes.txt"});
  EXPECT_EQ(slurp(folder / "notes.txt"), "mine");
  // An empty folder is fine; an unknown id is exit 2 and writes nothing.
  fs::create_directories(dir / "empty");
  EXPECT_EQ(runProcess(RTLAB_BINARY, {"exercise", "new", "pcss", "--out", (dir / "empty").string()}).exitCode, 0);
  const auto unknown = runProcess(RTLAB_BINARY, {"exercise", "new", "pcsss", "--out", (dir / "other").string()});
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_NE(unknown.err.find("did you mean 'pcss'"), std::string::npos) << unknown.err;
  EXPECT_FALSE(fs::exists(dir / "other"));
}

TEST(ExerciseCli, AFolderThatIsNotAnExerciseIsExit3) {
  const fs::path dir = freshTestDir("exercise");
  fs::create_directories(dir / "plain");
  const fs::path folder = newFolder("pcf", dir);
  const fs::path broken = dir / "broken";
  fs::copy(folder, broken, fs::copy_options::recursive);
  fs::remove(broken / folderFiles(broken).front());
  const fs::path badJson = dir / "bad_json";
  fs::copy(folder, badJson, fs::copy_options::recursive);
  writeText(badJson / "exercise.json", "{\"schema\": 1, \"exercise\": ");
  for (const auto& [path, expect] : std::vector<std::pair<fs::path, std::string>>{
           {dir / "plain", "no exercise.json"}, {dir / "missing", "no such directory"}, {broken, "missing shaders/"},
           {badJson, "not valid JSON"}}) {
    for (const char* command : {"grade", "render"}) {
      const auto r = std::string(command) == "grade"
                         ? runProcess(RTLAB_BINARY, {"exercise", "grade", path.string(), "--json"})
                         : runProcess(RTLAB_BINARY, {"render", "--exercise", path.string(), "--out", (dir / "x.png").string()});
      EXPECT_EQ(r.exitCode, 3) << command << " " << path << ": " << r.err;
      EXPECT_NE(r.err.find("is not an exercise folder"), std::string::npos) << r.err;
      EXPECT_NE(r.err.find(expect), std::string::npos) << r.err;
      EXPECT_TRUE(r.out.empty()) << r.out;
    }
  }
}

// Grading writes the report into its folder and nothing anywhere else: not into the student's
// folder, not into HOME or XDG caches (the workers turn Mesa's shader cache off).
TEST(ExerciseCli, GradingWritesNothingOutsideTheOutputFolder) {
  const fs::path dir = freshTestDir("exercise");
  const fs::path folder = newFolder("pcf", dir);
  const fs::path home = dir / "home";
  fs::create_directories(home);
  setenv("HOME", home.c_str(), 1);
  setenv("XDG_CACHE_HOME", (home / ".cache").c_str(), 1);
  std::map<std::string, std::string> before;
  for (const auto& e : fs::recursive_directory_iterator(folder))
    if (e.is_regular_file()) before[e.path().string()] = slurp(e.path());
  const auto mtimeBefore = fs::last_write_time(folder / folderFiles(folder).front());
  const Grade g = grade(folder, {"--views", firstViews("pcf", 2, dir).string(), "--report", (dir / "report").string()});
  ASSERT_EQ(g.process.exitCode, 0) << describe(g);
  std::map<std::string, std::string> after;
  for (const auto& e : fs::recursive_directory_iterator(folder))
    if (e.is_regular_file()) after[e.path().string()] = slurp(e.path());
  EXPECT_EQ(before, after) << "the student's folder changed";
  EXPECT_EQ(mtimeBefore, fs::last_write_time(folder / folderFiles(folder).front()));
  EXPECT_TRUE(fs::is_empty(home)) << "something was written under HOME";
  EXPECT_TRUE(fs::exists(dir / "report" / "index.html"));
  EXPECT_EQ(json::parse(slurp(dir / "report" / "grade.json")), g.result);
  // A second report into the same folder replaces it; a folder holding other files is refused (6).
  EXPECT_EQ(grade(folder, {"--views", firstViews("pcf", 1, dir).string(), "--report", (dir / "report").string()}).process.exitCode, 0);
  writeText(dir / "other.txt", "x");
  const Grade refused = grade(folder, {"--report", dir.string()});
  EXPECT_EQ(refused.process.exitCode, 6) << refused.process.err;
}

TEST(ExerciseCli, SolutionGradeIsTheSameOnEglAndOsmesa) {
  const fs::path dir = freshTestDir("exercise");
  const fs::path folder = newFolder("pcss", dir);
  copySolution(folder);
  const fs::path views = firstViews("pcss", 3, dir);
  const Grade egl = grade(folder, {"--views", views.string(), "--backend", "egl"});
  const Grade osmesa = grade(folder, {"--views", views.string(), "--backend", "osmesa"});
  ASSERT_EQ(egl.process.exitCode, 0) << describe(egl);
  ASSERT_EQ(osmesa.process.exitCode, 0) << describe(osmesa);
  EXPECT_EQ(egl.result["score"], 100);
  EXPECT_EQ(osmesa.result["score"], 100);
  for (std::size_t i = 0; i < egl.result["views"].size(); ++i) {
    json a = egl.result["views"][i], b = osmesa.result["views"][i];
    a.erase("ms");
    b.erase("ms");
    EXPECT_EQ(a, b);
  }
}

TEST(ExerciseCli, RenderWithExerciseUsesTheStudentsFilesAndActivatesTheTechnique) {
  const fs::path dir = freshTestDir("exercise");
  const fs::path folder = newFolder("shadow_map", dir);
  const auto student = runProcess(RTLAB_BINARY, {"render", "--exercise", folder.string(), "--size", "64x36", "--aov",
                                                 "visibility", "--out", (dir / "student.pfm").string()});
  ASSERT_EQ(student.exitCode, 0) << student.err;
  const auto shipped = runProcess(RTLAB_BINARY, {"render", "-t", "shadow_map", "--size", "64x36", "--aov", "visibility",
                                                 "--out", (dir / "shipped.pfm").string()});
  ASSERT_EQ(shipped.exitCode, 0) << shipped.err;
  const auto cmp = runProcess(RTLAB_BINARY, {"compare", (dir / "shipped.pfm").string(), (dir / "student.pfm").string(), "--json"});
  ASSERT_EQ(cmp.exitCode, 0) << cmp.err;
  EXPECT_GT(json::parse(cmp.out)["rmse"].get<double>(), 0.05) << "the stub (everything lit) differs from the shadows";
  copySolution(folder);
  ASSERT_EQ(runProcess(RTLAB_BINARY, {"render", "--exercise", folder.string(), "--size", "64x36", "--aov", "visibility",
                                      "--out", (dir / "solution.pfm").string()}).exitCode, 0);
  const auto same = runProcess(RTLAB_BINARY, {"compare", (dir / "shipped.pfm").string(), (dir / "solution.pfm").string(), "--json"});
  EXPECT_EQ(json::parse(same.out)["rmse"].get<double>(), 0.0);
}

// The report (docs/exercises.md "Report"): index.html and a page per view with the student's,
// the solution's and the reference's images, the difference heat map, the figures and the cause;
// it loads in headless Chromium without console errors, and its screenshot is not blank.
TEST(ExerciseCli, ReportPagesShowEveryViewAndOpenInChromium) {
  std::string why;
  ASSERT_TRUE(rtlab::test::chromiumAvailable(why)) << why;
  const fs::path dir = freshTestDir("exercise");
  const fs::path folder = newFolder("pcss", dir);
  const fs::path report = dir / "report";
  const Grade g = grade(folder, {"--views", firstViews("pcss", 3, dir).string(), "--report", report.string()});
  ASSERT_EQ(g.process.exitCode, 0) << describe(g);
  const std::string index = slurp(report / "index.html");
  for (const auto& v : g.result["views"]) {
    const std::string name = v["name"].get<std::string>();
    const fs::path page = report / ("view-" + name + ".html");
    EXPECT_NE(index.find("href=\"view-" + name + ".html\""), std::string::npos) << name;
    const std::string html = slurp(page);
    for (const char* caption : {"student", "solution", "reference (ground truth)", "|student - solution|", "RMSE vs solution",
                                "RMSE vs reference (solution)"})
      EXPECT_NE(html.find(caption), std::string::npos) << name << ": " << caption;
    EXPECT_NE(html.find("stub: the output is the stub"), std::string::npos) << name;
    std::size_t images = 0;
    for (auto at = html.find("data:image/png;base64,"); at != std::string::npos; at = html.find("data:image/png;base64,", at + 1)) ++images;
    EXPECT_EQ(images, 4u) << name;
  }
  const auto dom = rtlab::test::runChromium(report / "index.html", dir / "profile");
  ASSERT_EQ(dom.exitCode, 0) << dom.err;
  EXPECT_NE(dom.out.find("Score <b>0</b>"), std::string::npos) << dom.out.substr(0, 2000);
  EXPECT_TRUE(rtlab::test::consoleMessages(dom.err).empty()) << dom.err;
  const fs::path first = report / ("view-" + g.result["views"][0]["name"].get<std::string>() + ".html");
  const auto shot = rtlab::test::runChromium(first, dir / "profile2", dir / "view.png");
  ASSERT_EQ(shot.exitCode, 0) << shot.err;
  rtlab::test::expectNotBlank(rtlab::readImage((dir / "view.png").string()));
}

// Usage errors of `rtlab exercise` (docs/cli.md "rtlab exercise"): each one line, the documented code.
TEST(ExerciseCli, BadArgumentsAreOneLineErrorsWithTheDocumentedCode) {
  const fs::path dir = freshTestDir("exercise");
  const fs::path folder = newFolder("shadow_map", dir);
  writeText(dir / "bad.json", "{\"schema\": 1, \"views\": [{\"name\": \"x\"}]}");
  writeText(dir / "unknown_key.json", "{\"schema\": 1, \"views\": [{\"name\": \"x\", \"scene\": \"contact\", \"set\": {\"shadow.nope\": \"1\"}}]}");
  writeText(dir / "out_of_range.json", "{\"schema\": 1, \"views\": [{\"name\": \"y\", \"scene\": \"contact\", \"set\": {\"shadow.resolution\": \"1\"}}]}");
  const std::vector<std::pair<std::vector<std::string>, int>> cases = {
      {{"exercise"}, 2},
      {{"exercise", "frobnicate"}, 2},
      {{"exercise", "new", "pcss"}, 2},
      {{"exercise", "grade"}, 2},
      {{"exercise", "grade", folder.string(), "--time-limit", "0"}, 2},
      {{"exercise", "grade", folder.string(), "--time-limit", "abc"}, 2},
      {{"exercise", "grade", folder.string(), "--backend", "vulkan"}, 2},
      {{"exercise", "grade", folder.string(), "--views", (dir / "missing.json").string()}, 3},
      {{"exercise", "grade", folder.string(), "--views", (dir / "bad.json").string()}, 3},
      {{"exercise", "grade", folder.string(), "--views", (dir / "unknown_key.json").string()}, 2},
      {{"exercise", "grade", folder.string(), "--views", (dir / "out_of_range.json").string()}, 2},
      {{"exercise", "grade", folder.string(), "--report", (dir / "bad.json").string()}, 6},
      {{"exercise", "grade", folder.string(), "--cache", ""}, 2},
      {{"exercise", "grade", folder.string(), "--cache", (dir / "bad.json").string()}, 6},
      {{"exercise", "grade", folder.string(), "--cache", (dir / "bad.json" / "sub").string()}, 6},
  };
  for (const auto& [args, code] : cases) {
    const auto r = runProcess(RTLAB_BINARY, args);
    std::string joined;
    for (const auto& a : args) joined += a + " ";
    EXPECT_EQ(r.exitCode, code) << joined << ": " << r.err;
    EXPECT_EQ(rtlab::test::lineCount(r.err), 1) << joined << ": " << r.err;
    EXPECT_EQ(r.err.rfind("rtlab: error: ", 0), 0u) << r.err;
  }
  // A bad view is named.
  const auto r = runProcess(RTLAB_BINARY, {"exercise", "grade", folder.string(), "--views", (dir / "unknown_key.json").string()});
  EXPECT_NE(r.err.find("view 'x'"), std::string::npos) << r.err;
}

// A course author's views file with its own tolerance: a tolerance of 1 everywhere passes even the
// untouched stub, so the file's tolerance is the one applied.
TEST(ExerciseCli, ViewsFileToleranceReplacesTheExercises) {
  const fs::path dir = freshTestDir("exercise");
  const fs::path folder = newFolder("pcf", dir);
  json views = json::parse(slurp(firstViews("pcf", 2, dir)));
  views["tolerance"] = {{"pixel", 1.0}, {"fraction", 1.0}, {"rmse", 1.0}};
  writeText(dir / "lenient.json", views.dump());
  const Grade lenient = grade(folder, {"--views", (dir / "lenient.json").string()});
  ASSERT_EQ(lenient.process.exitCode, 0) << describe(lenient);
  EXPECT_EQ(lenient.result["score"], 100) << describe(lenient);
  const Grade strict = grade(folder, {"--views", firstViews("pcf", 2, dir).string()});
  EXPECT_EQ(strict.result["score"], 0) << describe(strict);
}

// A student's file may include rtlab's shaders only: an include of any other file on the machine is
// a compile error naming the student's file:line, and the other file's text appears nowhere.
TEST(ExerciseCli, StudentFilesIncludeOnlyShippedShaders) {
  const fs::path dir = freshTestDir("exercise");
  const fs::path folder = newFolder("shadow_map", dir);
  const fs::path secret = dir / "secret.glsl";
  writeText(secret, "SECRET_TOKEN_42\n");
  const std::string file = folderFiles(folder).front();
  const std::string text = slurp(folder / file);
  const std::vector<std::string> includes = {secret.string(), "../../../secret.glsl",
                                             "../../../../../../../../../../" + secret.relative_path().string()};
  for (const auto& include : includes) {
    SCOPED_TRACE(include);
    writeText(folder / file, "#include \"" + include + "\"\n" + text);
    const Grade g = grade(folder, {"--views", firstViews("shadow_map", 1, dir).string()});
    EXPECT_EQ(g.process.exitCode, 5) << describe(g);
    EXPECT_NE(g.process.err.find((folder / file).string() + ":1: an exercise file may include only files under shaders/"),
              std::string::npos) << g.process.err;
    EXPECT_EQ(g.process.err.find("SECRET_TOKEN_42"), std::string::npos);
    EXPECT_EQ(g.process.out.find("SECRET_TOKEN_42"), std::string::npos);
  }
  // (Includes of shipped shaders from a student's file work: ShippedSolutionScores100/pcss, whose
  // visibility.frag includes shadow_space.glsl and shadow_filter.glsl.)
}
