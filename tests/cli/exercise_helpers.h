// Helpers of the exercise tests (test_exercise.cpp, test_exercise_cache.cpp): make a student's
// folder, copy the shipped solution into it, grade it, and write views files.
#pragma once
#include "process.h"
#include "test_util.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace rtlab::test {

inline const std::filesystem::path kSource = RTLAB_SOURCE_DIR;

// `rtlab exercise new ID --out dir/student`; returns the folder.
inline std::filesystem::path newFolder(const std::string& id, const std::filesystem::path& dir) {
  const std::filesystem::path folder = dir / "student";
  const auto r = runProcess(RTLAB_BINARY, {"exercise", "new", id, "--out", folder.string()});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return folder;
}

inline std::vector<std::string> folderFiles(const std::filesystem::path& folder) {
  return nlohmann::json::parse(slurp(folder / "exercise.json"))["files"].get<std::vector<std::string>>();
}

// The shipped solution's files copied over the student's.
inline void copySolution(const std::filesystem::path& folder) {
  for (const auto& f : folderFiles(folder))
    std::filesystem::copy_file(kSource / f, folder / f, std::filesystem::copy_options::overwrite_existing);
}

struct Grade {
  ProcessResult process;
  nlohmann::json result;
};

inline Grade grade(const std::filesystem::path& folder, std::vector<std::string> extra = {}, int timeout = 300) {
  std::vector<std::string> args = {"exercise", "grade", folder.string(), "--json"};
  args.insert(args.end(), extra.begin(), extra.end());
  Grade g;
  g.process = runProcess(RTLAB_BINARY, args, timeout);
  try {
    g.result = nlohmann::json::parse(g.process.out);
  } catch (const nlohmann::json::exception&) {
  }
  return g;
}

inline std::string describe(const Grade& g) { return g.process.err + "\n" + g.result.dump(1); }

// A views file with the exercise's first `n` views.
inline std::filesystem::path firstViews(const std::string& id, std::size_t n, const std::filesystem::path& dir) {
  nlohmann::json def = nlohmann::json::parse(slurp(kSource / "assets" / "exercises" / (id + ".json")));
  nlohmann::json views = nlohmann::json::array();
  for (std::size_t i = 0; i < n && i < def["views"].size(); ++i) views.push_back(def["views"][i]);
  const std::filesystem::path path = dir / "views.json";
  writeText(path, nlohmann::json{{"schema", 1}, {"views", views}}.dump());
  return path;
}

// The grade cache the grading tests share (docs/exercises.md "The grade cache"): the solution's and
// the stubs' renders of a view are made once per build of rtlab, by whichever test needs them
// first; graders sharing it is safe (entries are written atomically, keyed by content). One folder
// per build of the binary (its size and time): the folders of earlier builds, whose entries no grade
// can hit again, are removed, so that rebuilding does not pile them up under the build folder.
inline std::vector<std::string> sharedGradeCache() {
  namespace fs = std::filesystem;
  const fs::path root = fs::path(RTLAB_TEST_TMP) / "grade-cache";
  std::error_code ec;
  const auto stamp = static_cast<unsigned long long>(fs::last_write_time(RTLAB_BINARY, ec).time_since_epoch().count());
  const std::string name = "rtlab-" + std::to_string(fs::file_size(RTLAB_BINARY, ec)) + "-" + std::to_string(stamp);
  for (const auto& entry : fs::directory_iterator(root, ec))
    if (entry.path().filename() != name) fs::remove_all(entry.path(), ec);
  return {"--cache", (root / name).string()};
}

} // namespace rtlab::test
