// GL errors counted everywhere (docs/testing.md "GL errors"): synchronous debug output on every
// backend, the process total that draining a frame's errors does not drop, rtlab's exit report,
// and the per-test listener, shown to fail in a child run of this binary.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "gl/debug.h"
#include "gl_error_check.h"
#include "process.h"
#include "render_fixture.h"

namespace rtlab {
namespace {

// A texture name never generated: binding it is GL_INVALID_OPERATION in a core profile.
constexpr GLuint kNeverGenerated = 0x7ffffff0u;

std::string thisBinary() { return std::filesystem::read_symlink("/proc/self/exe").string(); }

TEST(GlErrors, DebugOutputCountsAnErrorInsideTheCall) {
  testContext().makeCurrent();
  EXPECT_TRUE(glIsEnabled(GL_DEBUG_OUTPUT));
  EXPECT_TRUE(glIsEnabled(GL_DEBUG_OUTPUT_SYNCHRONOUS));
  ExpectGlErrors expected(1);
  const std::int64_t before = glErrorTotal();
  glBindTexture(GL_TEXTURE_2D, kNeverGenerated);
  // Synchronous output: counted by the callback inside the call, before anything polls glGetError.
  EXPECT_EQ(glErrorTotal(), before + 1) << "on " << testContext().backendName();
  const auto messages = glErrorMessagesSince(before);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].rfind("GL api error: ", 0), 0u) << messages[0];
}

TEST(GlErrors, ContextIsADebugContextWhereThePlatformHasTheAttribute) {
  testContext().makeCurrent();
  GLint flags = 0;
  glGetIntegerv(GL_CONTEXT_FLAGS, &flags);
  // EGL has EGL_CONTEXT_OPENGL_DEBUG; OSMesa has no such attribute (debug output is enabled on its
  // plain context, DebugOutputCountsAnErrorInsideTheCall).
  const bool egl = testContext().backendName().rfind("egl", 0) == 0;
  EXPECT_EQ((flags & GL_CONTEXT_FLAG_DEBUG_BIT) != 0, egl) << testContext().backendName() << ", flags " << flags;
}

TEST(GlErrors, DrainingAFrameKeepsTheErrorInTheProcessTotal) {
  testContext().makeCurrent();
  ExpectGlErrors expected(1);
  const std::int64_t before = glErrorTotal();
  glBindTexture(GL_TEXTURE_2D, kNeverGenerated); // outside any frame, as a set-up error would be
  EXPECT_EQ(drainGlErrors(), 1);                 // renderMeasured drains set-up errors before its frames
  EXPECT_EQ(drainGlErrors(), 0);                 // the frame counter starts afresh
  EXPECT_EQ(glErrorTotal(), before + 1);         // the total keeps it
}

TEST(GlErrors, AnErrorWithoutADebugMessageCountsOnceWhenDrained) {
  testContext().makeCurrent();
  ExpectGlErrors expected(1);
  const std::int64_t before = glErrorTotal();
  glDisable(GL_DEBUG_OUTPUT); // as on a context without KHR_debug: glGetError alone reports it
  glBindTexture(GL_TEXTURE_2D, kNeverGenerated);
  glEnable(GL_DEBUG_OUTPUT);
  EXPECT_EQ(glErrorTotal(), before); // no callback: not counted yet
  EXPECT_EQ(drainGlErrors(), 1);
  EXPECT_EQ(drainGlErrors(), 0);
  EXPECT_EQ(glErrorTotal(), before + 1);
  const auto messages = glErrorMessagesSince(before);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0], "glGetError: GL_INVALID_OPERATION (no debug message)");
}

TEST(GlErrors, AppendGlErrorReportWritesTheTotalAndTheMessages) {
  testContext().makeCurrent();
  {
    ExpectGlErrors expected(1);
    glBindTexture(GL_TEXTURE_2D, kNeverGenerated);
  }
  const std::filesystem::path path =
      std::filesystem::path(RTLAB_TEST_TMP) / ("gl_report_" + std::to_string(::getpid()) + ".txt");
  std::filesystem::create_directories(path.parent_path());
  std::filesystem::remove(path);
  ASSERT_TRUE(appendGlErrorReport(path.string(), "first"));
  ASSERT_TRUE(appendGlErrorReport(path.string(), "second"));
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::filesystem::remove(path);
  const std::string head = "gl_errors: " + std::to_string(glErrorTotal());
  EXPECT_NE(text.str().find(head + " first\n"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find(head + " second\n"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("\n  GL api error: "), std::string::npos) << text.str();
}

// Run only by UndeclaredErrorOutsideAFrameFailsItsTest, in a child process: must fail there.
TEST(GlErrorsDeliberate, DISABLED_UndeclaredErrorOutsideAFrame) {
  testContext().makeCurrent();
  setLogLevel(LogLevel::Quiet);
  glBindTexture(GL_TEXTURE_2D, kNeverGenerated); // as a bad bind during a test's set-up would
}

// Run only by DeclaredCountThatDiffersFailsItsTest, in a child process: must fail there.
TEST(GlErrorsDeliberate, DISABLED_DeclaredCountDiffers) {
  testContext().makeCurrent();
  ExpectGlErrors expected(2);
  glBindTexture(GL_TEXTURE_2D, kNeverGenerated);
}

test::ProcessResult runDeliberate(const std::string& name, int expectedGlErrors) {
  return test::runProcess(thisBinary(),
                          {"--gtest_filter=GlErrorsDeliberate.DISABLED_" + name, "--gtest_also_run_disabled_tests"}, 120,
                          -1, expectedGlErrors);
}

TEST(GlErrors, UndeclaredErrorOutsideAFrameFailsItsTest) {
  // The child's one error is reported to this test (runProcess's expectedGlErrors), not to the suite.
  const auto r = runDeliberate("UndeclaredErrorOutsideAFrame", 1);
  EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("1 GL error(s) in this test"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("GL api error: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("[  FAILED  ] GlErrorsDeliberate.DISABLED_UndeclaredErrorOutsideAFrame"), std::string::npos)
      << r.out;
  EXPECT_NE(r.glReport.find("gl_errors: 1 rtlab_render_tests"), std::string::npos) << r.glReport;
}

TEST(GlErrors, DeclaredCountThatDiffersFailsItsTest) {
  const auto r = runDeliberate("DeclaredCountDiffers", 0); // the one error is declared: not in the total
  EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("GL errors made in an ExpectGlErrors scope"), std::string::npos) << r.out;
  EXPECT_NE(r.glReport.find("gl_errors: 0 rtlab_render_tests"), std::string::npos) << r.glReport;
}

} // namespace
} // namespace rtlab
