// GL errors of the rtlab processes the command-line tests run (docs/testing.md "GL errors"): rtlab
// reports its total at exit to RTLAB_GL_ERRORS_FILE (docs/contract.md "GL error report"), and
// runProcess fails the test when a child reported errors, shown in a child run of this binary.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>

#include "process.h"

namespace rtlab::test {
namespace {

TEST(GlErrorReport, RtlabReportsItsTotalAtExit) {
  const std::filesystem::path out =
      std::filesystem::path(RTLAB_TEST_TMP) / ("gl_report_" + std::to_string(::getpid()) + ".png");
  std::filesystem::create_directories(out.parent_path());
  const auto r = runProcess(RTLAB_BINARY, {"render", "--size", "32x18", "--out", out.string()});
  std::filesystem::remove(out);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.glReport.rfind("gl_errors: 0 rtlab render (pid ", 0), 0u) << r.glReport;
}

TEST(GlErrorReport, RtlabReportsEvenWhenTheCommandFails) {
  const auto r = runProcess(RTLAB_BINARY, {"render", "--scene", "no_such_scene"});
  EXPECT_NE(r.exitCode, 0);
  EXPECT_EQ(r.glReport.rfind("gl_errors: 0 rtlab render (pid ", 0), 0u) << r.glReport;
}

// Run only by AChildThatReportsErrorsFailsItsTest, in a child process: must fail there. The
// grandchild stands for an rtlab process that made two GL errors.
TEST(GlErrorReportDeliberate, DISABLED_ChildReportsErrors) {
  runProcess("/bin/sh", {"-c", "printf 'gl_errors: 2 rtlab render (pid 1)\\n  GL api error: made up\\n' >> \"$RTLAB_GL_ERRORS_FILE\""});
}

TEST(GlErrorReport, AChildThatReportsErrorsFailsItsTest) {
  // The grandchild's two errors reach this test through the child's own report (expected here).
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  const auto r = runProcess(self, {"--gtest_filter=GlErrorReportDeliberate.DISABLED_ChildReportsErrors",
                                   "--gtest_also_run_disabled_tests"},
                            60, -1, 2);
  EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("GL errors reported by '/bin/sh"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("GL api error: made up"), std::string::npos) << r.out;
  EXPECT_NE(r.glReport.find("gl_errors: 2 rtlab_cli_tests"), std::string::npos) << r.glReport;
}

} // namespace
} // namespace rtlab::test
