// scripts/check_build_dir.sh, which scripts/test.sh runs before building: build/ without the
// render and CLI tests, a sanitizer directory without the sanitizers (the whole-suite one also
// without the render and CLI tests), a TSan directory without TSan, or any without tests, is
// refused with one line and exit 1, so the suite never passes with tests silently missing; a fresh
// directory or a fitting one passes.
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

TEST(CheckBuildDir, RefusesAFullBuildWithoutRenderAndCliTests) {
  const auto release = check(buildDir("release_unit_only", "RTLAB_UNIT_ONLY:BOOL=ON\n"), "full");
  EXPECT_EQ(release.exitCode, 1) << release.err;
  EXPECT_NE(release.err.find("RTLAB_UNIT_ONLY=ON: it has no render or CLI tests"), std::string::npos) << release.err;
  const auto unitOnly =
      check(buildDir("unit_only", "RTLAB_SANITIZE:BOOL=ON\nRTLAB_UNIT_ONLY:BOOL=ON\nBUILD_TESTING:BOOL=ON\n"), "sanitizer-full");
  EXPECT_EQ(unitOnly.exitCode, 1) << unitOnly.err;
  EXPECT_NE(unitOnly.err.find("RTLAB_UNIT_ONLY=ON: it has no render or CLI tests"), std::string::npos) << unitOnly.err;
  const auto noTests =
      check(buildDir("no_tests", "RTLAB_SANITIZE:BOOL=ON\nRTLAB_UNIT_ONLY:BOOL=OFF\nBUILD_TESTING:BOOL=OFF\n"), "sanitizer-full");
  EXPECT_EQ(noTests.exitCode, 1) << noTests.err;
  EXPECT_NE(noTests.err.find("BUILD_TESTING=OFF"), std::string::npos) << noTests.err;
  // CMake's other spellings of true count too.
  const auto yes = check(buildDir("unit_only_yes", "RTLAB_SANITIZE:BOOL=1\nRTLAB_UNIT_ONLY:BOOL=yes\n"), "sanitizer-full");
  EXPECT_EQ(yes.exitCode, 1) << yes.err;
  EXPECT_EQ(check(buildDir("no_tests_full", "BUILD_TESTING:BOOL=OFF\n"), "full").exitCode, 1);
}

TEST(CheckBuildDir, RefusesASanitizerDirectoryWithoutTheSanitizers) {
  // A full build (render and CLI tests) whose tests would run unsanitized: the old build/.
  const auto plain = check(buildDir("plain", "RTLAB_UNIT_ONLY:BOOL=OFF\nRTLAB_SANITIZE:BOOL=OFF\n"), "sanitizer");
  EXPECT_EQ(plain.exitCode, 1) << plain.err;
  EXPECT_NE(plain.err.find("RTLAB_SANITIZE=OFF"), std::string::npos) << plain.err;
  // Absent means off: a directory configured without the option is not sanitized.
  EXPECT_EQ(check(buildDir("absent", "BUILD_TESTING:BOOL=ON\n"), "sanitizer").exitCode, 1);
  EXPECT_EQ(check(buildDir("plain_full", "RTLAB_UNIT_ONLY:BOOL=OFF\n"), "sanitizer-full").exitCode, 1);
  const auto noTsan = check(buildDir("no_tsan", "RTLAB_TSAN:BOOL=OFF\nRTLAB_SANITIZE:BOOL=ON\n"), "tsan");
  EXPECT_EQ(noTsan.exitCode, 1) << noTsan.err;
  EXPECT_NE(noTsan.err.find("RTLAB_TSAN=OFF"), std::string::npos) << noTsan.err;
  const auto tsanNoTests = check(buildDir("tsan_no_tests", "RTLAB_TSAN:BOOL=ON\nBUILD_TESTING:BOOL=OFF\n"), "tsan");
  EXPECT_EQ(tsanNoTests.exitCode, 1) << tsanNoTests.err;
}

TEST(CheckBuildDir, AcceptsFreshAndFittingDirectories) {
  EXPECT_EQ(check(buildDir("fresh", ""), "sanitizer").exitCode, 0);
  EXPECT_EQ(check(buildDir("fresh_tsan", ""), "tsan").exitCode, 0);
  EXPECT_EQ(check(buildDir("fresh_full", ""), "full").exitCode, 0);
  EXPECT_EQ(check(buildDir("release", "CMAKE_BUILD_TYPE:STRING=Release\nRTLAB_UNIT_ONLY:BOOL=OFF\n"), "full").exitCode, 0);
  const auto asan =
      check(buildDir("asan", "RTLAB_UNIT_ONLY:BOOL=OFF\nRTLAB_SANITIZE:BOOL=ON\nBUILD_TESTING:BOOL=ON\n"), "sanitizer-full");
  EXPECT_EQ(asan.exitCode, 0) << asan.err;
  // The CI's sanitizer build holds the unit tests and the fuzz replays: unit-only is what it is.
  const auto asanUnit = check(buildDir("asan_unit", "RTLAB_UNIT_ONLY:BOOL=ON\nRTLAB_SANITIZE:BOOL=ON\n"), "sanitizer");
  EXPECT_EQ(asanUnit.exitCode, 0) << asanUnit.err;
  // The TSan build is unit-only by design (it builds rtlab_tsan_tests alone).
  const auto tsan = check(buildDir("tsan", "RTLAB_UNIT_ONLY:BOOL=ON\nRTLAB_TSAN:BOOL=ON\n"), "tsan");
  EXPECT_EQ(tsan.exitCode, 0) << tsan.err;
  EXPECT_EQ(check(buildDir("usage", ""), "release").exitCode, 2);
}

} // namespace
} // namespace check_build_dir_test
