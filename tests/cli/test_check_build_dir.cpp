// scripts/check_build_dir.sh, which scripts/test.sh runs before building: a build directory
// configured without the render and CLI tests (or a sanitizer directory without the sanitizers,
// or any without tests) is refused with one line and exit 1, so the suite never passes with tests
// silently missing; a fresh directory or a fitting one passes.
#include "process.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using rtlab::test::runProcess;

namespace check_build_dir_test {
namespace {

// A build directory whose CMakeCache.txt holds `entries` (empty: no cache at all).
fs::path buildDir(const std::string& name, const std::string& entries) {
  const fs::path dir = fs::path(RTLAB_TEST_TMP) / "cli_check_build_dir" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  if (!entries.empty()) std::ofstream(dir / "CMakeCache.txt") << "# CMake cache\n" << entries;
  return dir;
}

rtlab::test::ProcessResult check(const fs::path& dir, const std::string& kind) {
  return runProcess("/bin/bash", {std::string(RTLAB_SOURCE_DIR) + "/scripts/check_build_dir.sh", dir.string(), kind},
                    30);
}

TEST(CheckBuildDir, RefusesABuildWithoutRenderAndCliTests) {
  const auto unitOnly = check(buildDir("unit_only", "RTLAB_UNIT_ONLY:BOOL=ON\nBUILD_TESTING:BOOL=ON\n"), "full");
  EXPECT_EQ(unitOnly.exitCode, 1) << unitOnly.err;
  EXPECT_NE(unitOnly.err.find("RTLAB_UNIT_ONLY=ON: it has no render or CLI tests"), std::string::npos) << unitOnly.err;
  const auto noTests = check(buildDir("no_tests", "RTLAB_UNIT_ONLY:BOOL=OFF\nBUILD_TESTING:BOOL=OFF\n"), "full");
  EXPECT_EQ(noTests.exitCode, 1) << noTests.err;
  EXPECT_NE(noTests.err.find("BUILD_TESTING=OFF"), std::string::npos) << noTests.err;
  // CMake's other spellings of true count too.
  const auto yes = check(buildDir("unit_only_yes", "RTLAB_UNIT_ONLY:BOOL=yes\n"), "full");
  EXPECT_EQ(yes.exitCode, 1) << yes.err;
}

TEST(CheckBuildDir, RefusesASanitizerDirectoryWithoutTheSanitizers) {
  const auto plain = check(buildDir("plain", "RTLAB_UNIT_ONLY:BOOL=ON\nRTLAB_SANITIZE:BOOL=OFF\n"), "sanitizer");
  EXPECT_EQ(plain.exitCode, 1) << plain.err;
  EXPECT_NE(plain.err.find("RTLAB_SANITIZE=OFF"), std::string::npos) << plain.err;
}

TEST(CheckBuildDir, AcceptsFreshAndFittingDirectories) {
  EXPECT_EQ(check(buildDir("fresh", ""), "full").exitCode, 0);
  EXPECT_EQ(check(buildDir("fresh_asan", ""), "sanitizer").exitCode, 0);
  const auto full = check(buildDir("full", "RTLAB_UNIT_ONLY:BOOL=OFF\nRTLAB_SANITIZE:BOOL=OFF\nBUILD_TESTING:BOOL=ON\n"), "full");
  EXPECT_EQ(full.exitCode, 0) << full.err;
  const auto asan = check(buildDir("asan", "RTLAB_UNIT_ONLY:BOOL=ON\nRTLAB_SANITIZE:BOOL=ON\n"), "sanitizer");
  EXPECT_EQ(asan.exitCode, 0) << asan.err;
  // This checkout's own build directory, as scripts/test.sh would check it.
  const auto own = check(fs::path(RTLAB_BINARY).parent_path(), "full");
  EXPECT_EQ(own.exitCode, 0) << own.err;
  EXPECT_EQ(check(buildDir("usage", ""), "other").exitCode, 2);
}

} // namespace
} // namespace check_build_dir_test
