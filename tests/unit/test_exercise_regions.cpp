// Exercise regions (docs/exercises.md "Regions"): the grammar of the markers, the student's copy,
// and every region shipped under shaders/ with the definitions under assets/exercises/.
#include "exercise/exercise_def.h"
#include "exercise/regions.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace rtlab;
using rtlab::test::catchError;
using rtlab::test::checkCaught;

namespace {

const char* kFile = R"(float f(float x) {
  // exercise(demo-part): begin
  // task: Return twice x.
  // task: (no clamp)
  float y = 2.0 * x;
  return y;
  // exercise: stub
  // // nothing yet
  // return 0.0;
  //
  // exercise: end
}
float g(float x) {
  // exercise(other-part): begin
  // task: Return x squared.
  return x * x;
  // exercise: stub
  // return 1.0;
  // exercise: end
}
)";

std::string withLine(const std::string& text, const std::string& find, const std::string& replace) {
  return rtlab::test::replacedOnce(text, find, replace);
}

} // namespace

TEST(ExerciseRegions, ParsesNameTaskSolutionAndStub) {
  const auto regions = parseExerciseRegions(kFile, "demo.glsl");
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_EQ(regions[0].name, "demo-part");
  EXPECT_EQ(regions[0].beginLine, 2);
  EXPECT_EQ(regions[0].endLine, 11);
  EXPECT_EQ(regions[0].task, (std::vector<std::string>{"Return twice x.", "(no clamp)"}));
  EXPECT_EQ(regions[0].solution, (std::vector<std::string>{"  float y = 2.0 * x;", "  return y;"}));
  // The stub's comment markers are removed, keeping the indentation; "//" alone is an empty line.
  EXPECT_EQ(regions[0].stub, (std::vector<std::string>{"  // nothing yet", "  return 0.0;", ""}));
  EXPECT_EQ(regions[1].name, "other-part");
}

TEST(ExerciseRegions, StudentCopyStubsTheChosenRegionsAndStripsTheOthers) {
  const std::string copy = studentCopy(kFile, "demo.glsl", {"demo-part"});
  EXPECT_EQ(copy.find("2.0 * x"), std::string::npos) << copy;        // solution gone
  EXPECT_NE(copy.find("  return 0.0;\n"), std::string::npos) << copy; // stub is code now
  EXPECT_NE(copy.find(kStubNotice), std::string::npos) << copy;      // and says it is a stub
  EXPECT_NE(copy.find("// task: Return twice x."), std::string::npos);
  EXPECT_NE(copy.find("// exercise(demo-part): begin"), std::string::npos);
  // The other region keeps its solution without markers.
  EXPECT_NE(copy.find("  return x * x;\n"), std::string::npos) << copy;
  EXPECT_EQ(copy.find("other-part"), std::string::npos) << copy;
  EXPECT_EQ(copy.find("return 1.0;"), std::string::npos) << copy;
  // Lines outside regions are unchanged, and the copy still parses as a student's file.
  EXPECT_EQ(copy.rfind("float f(float x) {\n", 0), 0u);
  const auto regions = parseExerciseRegions(copy, "copy.glsl", true);
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_EQ(regions[0].name, "demo-part");
}

TEST(ExerciseRegions, StudentCopyWithNoChosenRegionIsTheSolutionWithoutMarkers) {
  const std::string copy = studentCopy(kFile, "demo.glsl", {});
  EXPECT_EQ(copy.find("exercise"), std::string::npos) << copy;
  EXPECT_NE(copy.find("float y = 2.0 * x;"), std::string::npos);
}

TEST(ExerciseRegions, MalformedMarkersNameFileAndLine) {
  struct Case {
    std::string text;
    std::string expect;
  };
  const std::vector<Case> cases = {
      {withLine(kFile, "  // exercise: end\n}\nfloat g", "}\nfloat g"), "demo.glsl:11: stub line of region 'demo-part' must be a comment"},
      {withLine(kFile, "  // task: Return x squared.\n", ""), "demo.glsl:14: region 'other-part' has no '// task:' line"},
      {withLine(kFile, "  // exercise: stub\n  // return 1.0;\n", ""), "region 'other-part' ends without '// exercise: stub'"},
      {withLine(kFile, "  // return 1.0;", "  return 1.0;"), "demo.glsl:18: stub line of region 'other-part' must be a comment"},
      {withLine(kFile, "  // exercise(other-part): begin\n", ""), "demo.glsl:14: a '// task:' line belongs right after"},
      {withLine(kFile, "exercise(demo-part)", "exercise(Demo Part)"), "demo.glsl:2: malformed exercise marker"},
      {withLine(kFile, "  float y = 2.0 * x;\n", "  // exercise(inner): begin\n  float y = 2.0 * x;\n"),
       "demo.glsl:5: exercise region 'inner' begins inside region 'demo-part' (line 2)"},
      {withLine(kFile, "  // exercise(other-part): begin\n  // task: Return x squared.\n", ""), "demo.glsl:15: '// exercise: stub' outside a region"},
      {std::string(kFile) + "// exercise(tail): begin\n// task: x\nfoo();\n", "demo.glsl:21: exercise region 'tail' has no '// exercise: end'"},
      {withLine(kFile, "  float y = 2.0 * x;\n  return y;\n", ""), "region 'demo-part' has no solution lines before its stub"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.expect);
    checkCaught(catchError([&] { parseExerciseRegions(c.text, "demo.glsl"); }), ExitCode::Input, {c.expect});
  }
}

// Every marker shipped under shaders/ is well formed, every region name is unique and used by an
// exercise, and every exercise's regions exist (the catalog loads).
TEST(ExerciseRegions, ShippedMarkersAndDefinitionsAreWellFormed) {
  std::vector<RegionLocation> regions;
  ASSERT_FALSE(catchError([&] { regions = shippedRegions(); }).thrown) << catchError([&] { shippedRegions(); }).message;
  const auto caught = catchError([] { exerciseCatalog(); });
  ASSERT_FALSE(caught.thrown) << caught.message;
  std::set<std::string> used;
  for (const auto& def : exerciseCatalog()) {
    used.insert(def.regions.begin(), def.regions.end());
    EXPECT_FALSE(def.files.empty()) << def.id;
    for (const auto& file : def.files) EXPECT_EQ(file.rfind("shaders/", 0), 0u) << def.id << ": " << file;
  }
  for (const auto& r : regions) EXPECT_TRUE(used.count(r.region)) << r.file << ": region '" << r.region << "' belongs to no exercise";
}

// Each technique folder has an exercise with its id (docs/contract.md "Exercises"), with views
// that cover what docs/exercises.md asks of them.
TEST(ExerciseRegions, EveryTechniqueHasAnExerciseWithEnoughViews) {
  namespace fs = std::filesystem;
  std::set<std::string> ids;
  for (const auto& def : exerciseCatalog()) ids.insert(def.id);
  for (const auto& entry : fs::directory_iterator(fs::path(RTLAB_SOURCE_DIR) / "techniques")) {
    if (!entry.is_directory() || entry.path().filename() == "common") continue;
    const std::string id = entry.path().filename().string();
    EXPECT_TRUE(ids.count(id)) << "technique '" << id << "' has no exercise (assets/exercises/" << id << ".json)";
  }
  for (const auto& def : exerciseCatalog()) {
    SCOPED_TRACE(def.id);
    std::set<std::string> scenes;
    int hidden = 0, changed = 0;
    for (const auto& v : def.views) {
      scenes.insert(v.scene);
      hidden += v.hidden ? 1 : 0;
      changed += v.set.empty() ? 0 : 1;
    }
    EXPECT_GE(def.views.size(), 4u);
    EXPECT_GE(scenes.size(), 2u);
    EXPECT_GE(hidden, 1);
    EXPECT_GE(changed, 1);
  }
}
