// `rtlab exercise grade --cache CACHEDIR` (docs/exercises.md "The grade cache"): a grade that finds
// the solution and the stubs in the cache renders only the student's files (the phase lines on
// stderr say so) and gives the JSON of a grade without the cache; a corrupt entry is reported,
// rendered again and overwritten; a changed view or a changed shipped file misses the cache.
#include "exercise_helpers.h"
#include "process.h"
#include "test_util.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using nlohmann::json;
using namespace rtlab::test;

namespace {

// The JSON without the measured times (`ms`, the student's render: it varies from run to run).
json withoutTimes(json j) {
  for (auto& v : j["views"]) v.erase("ms");
  return j;
}

std::vector<fs::path> entries(const fs::path& cache) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(cache)) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string fromCache(std::size_t hits, std::size_t views, const char* what) {
  return std::to_string(hits) + " of " + std::to_string(views) + " views with " + what + " from the cache";
}

std::string rendering(std::size_t views, const char* what) {
  return "rendering " + std::to_string(views) + " views with " + what + "\n";
}

} // namespace

// The untouched folder fails with the stub cause, so its grade renders the solution, the references
// and the stubs: the second grade takes all of them from the cache.
TEST(ExerciseCache, SecondGradeRendersOnlyTheStudentsFilesAndGivesTheSameJson) {
  const fs::path dir = freshTestDir("exercise");
  const fs::path folder = newFolder("pcf", dir);
  const std::string views = firstViews("pcf", 2, dir).string();
  const std::vector<std::string> cache = {"--views", views, "--cache", (dir / "cache").string()};
  const Grade fresh = grade(folder, {"--views", views});
  const Grade first = grade(folder, cache);
  const Grade second = grade(folder, cache);
  for (const Grade* g : {&fresh, &first, &second}) ASSERT_EQ(g->process.exitCode, 0) << describe(*g);
  ASSERT_EQ(first.result["views"].size(), 2u);
  EXPECT_EQ(first.result["score"], 0) << "both views fail with the stub, so both stubs are rendered: " << describe(first);

  EXPECT_TRUE(has(first.process.err, fromCache(0, 2, "the solution"))) << first.process.err;
  EXPECT_TRUE(has(first.process.err, rendering(2, "the solution"))) << first.process.err;
  EXPECT_TRUE(has(first.process.err, rendering(2, "the stubs"))) << first.process.err;
  EXPECT_EQ(entries(dir / "cache").size(), 4u) << "two solution entries (with the references) and two stubs";

  EXPECT_TRUE(has(second.process.err, fromCache(2, 2, "the solution"))) << second.process.err;
  EXPECT_TRUE(has(second.process.err, fromCache(2, 2, "the stubs"))) << second.process.err;
  EXPECT_TRUE(has(second.process.err, rendering(2, "the student's files"))) << second.process.err;
  EXPECT_FALSE(has(second.process.err, "with the solution\n")) << second.process.err;
  EXPECT_FALSE(has(second.process.err, "with the stubs\n")) << second.process.err;
  EXPECT_FALSE(has(second.process.err, "warning")) << second.process.err;

  // Every figure (RMSEs against the solution and the reference, the differing fraction) is the
  // fresh grade's to the last bit: the cached images are the rendered ones.
  EXPECT_EQ(withoutTimes(first.result), withoutTimes(fresh.result));
  EXPECT_EQ(withoutTimes(second.result), withoutTimes(fresh.result));
  EXPECT_EQ(entries(dir / "cache").size(), 4u) << "nothing is added by a grade that hits";
}

// A truncated entry, one with a flipped byte in its images and one that is not an entry at all
// are each reported in one warning line, rendered again, and overwritten with a sound entry.
TEST(ExerciseCache, CorruptEntriesAreRenderedAgainAndOverwritten) {
  const fs::path dir = freshTestDir("exercise");
  const fs::path folder = newFolder("pcf", dir);
  copySolution(folder);
  const std::string views = firstViews("pcf", 3, dir).string();
  const std::vector<std::string> cache = {"--views", views, "--cache", (dir / "cache").string()};
  const Grade first = grade(folder, cache);
  ASSERT_EQ(first.process.exitCode, 0) << describe(first);
  EXPECT_EQ(first.result["score"], 100) << describe(first);
  const auto files = entries(dir / "cache");
  ASSERT_EQ(files.size(), 3u) << "the solution passes: no stub is rendered";
  const std::string sound = slurp(files[1]);
  writeText(files[0], slurp(files[0]).substr(0, slurp(files[0]).size() / 2));
  std::string flipped = sound;
  flipped[flipped.size() - 5] = char(flipped[flipped.size() - 5] ^ 0x40);
  writeText(files[1], flipped);
  writeText(files[2], "not an entry");

  const Grade second = grade(folder, cache);
  ASSERT_EQ(second.process.exitCode, 0) << describe(second);
  EXPECT_EQ(withoutTimes(second.result), withoutTimes(first.result));
  int warnings = 0;
  for (std::size_t at = second.process.err.find("rtlab: warning: grade cache entry "); at != std::string::npos;
       at = second.process.err.find("rtlab: warning: grade cache entry ", at + 1))
    ++warnings;
  EXPECT_EQ(warnings, 3) << second.process.err;
  for (const auto& f : files) EXPECT_TRUE(has(second.process.err, f.string() + " is corrupt")) << second.process.err;
  EXPECT_TRUE(has(second.process.err, "truncated")) << second.process.err;
  EXPECT_TRUE(has(second.process.err, "do not match their hash")) << second.process.err;
  EXPECT_TRUE(has(second.process.err, rendering(3, "the solution"))) << second.process.err;
  EXPECT_EQ(slurp(files[1]), sound) << "the entry is written again as it was first written";

  const Grade third = grade(folder, cache);
  EXPECT_TRUE(has(third.process.err, fromCache(3, 3, "the solution"))) << third.process.err;
  EXPECT_FALSE(has(third.process.err, "warning")) << third.process.err;
  EXPECT_EQ(entries(dir / "cache"), files) << "no temporary file is left";
}

// A view whose definition changed, and every view after a shipped shader changed, miss the cache.
TEST(ExerciseCache, AChangedViewOrShippedFileMissesTheCache) {
  const fs::path dir = freshTestDir("exercise");
  const fs::path folder = newFolder("pcf", dir);
  copySolution(folder);
  json views = json::parse(slurp(firstViews("pcf", 2, dir)));
  const std::string cacheDir = (dir / "cache").string();
  const Grade first = grade(folder, {"--views", (dir / "views.json").string(), "--cache", cacheDir});
  ASSERT_EQ(first.process.exitCode, 0) << describe(first);

  views["views"][1]["size"] = "96x54";
  writeText(dir / "changed.json", views.dump());
  const Grade changedView = grade(folder, {"--views", (dir / "changed.json").string(), "--cache", cacheDir});
  ASSERT_EQ(changedView.process.exitCode, 0) << describe(changedView);
  EXPECT_TRUE(has(changedView.process.err, fromCache(1, 2, "the solution"))) << changedView.process.err;
  EXPECT_TRUE(has(changedView.process.err, rendering(1, "the solution"))) << changedView.process.err;

  // The same views with a data folder whose solution file differs (by a comment: the key hashes
  // content, it does not judge whether a change matters).
  const fs::path data = dir / "data";
  fs::create_directories(data);
  fs::copy(kSource / "shaders", data / "shaders", fs::copy_options::recursive);
  fs::copy(kSource / "assets", data / "assets", fs::copy_options::recursive);
  const std::string file = folderFiles(folder).front();
  writeText(data / file, slurp(data / file) + "\n// changed\n");
  ::setenv("RTLAB_DATA_DIR", data.c_str(), 1);
  const Grade changedFile = grade(folder, {"--views", (dir / "views.json").string(), "--cache", cacheDir});
  ::unsetenv("RTLAB_DATA_DIR");
  ASSERT_EQ(changedFile.process.exitCode, 0) << describe(changedFile);
  EXPECT_EQ(changedFile.result["score"], 100) << describe(changedFile);
  EXPECT_TRUE(has(changedFile.process.err, fromCache(0, 2, "the solution"))) << changedFile.process.err;
  EXPECT_TRUE(has(changedFile.process.err, rendering(2, "the solution"))) << changedFile.process.err;
}
