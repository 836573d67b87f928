#include "gl_error_check.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>

#include "gl/debug.h"
#include "gl_error_report.h"

namespace rtlab {
namespace {

// Declared errors (ExpectGlErrors adds them): of the running test, excused by the listener, and of
// the whole process, left out of the binary's total.
std::int64_t g_excusedInTest = 0;
std::int64_t g_declaredInProcess = 0;

std::string messagesSince(std::int64_t mark) {
  std::ostringstream out;
  for (const std::string& m : glErrorMessagesSince(mark)) out << "\n  " << m;
  return out.str();
}

// The total after the current context's glGetError queue is drained: errors that no debug message
// reported count too, and the next frame's counter does not inherit this test's errors.
std::int64_t drainedTotal() {
  drainGlErrors();
  return glErrorTotal();
}

class GlErrorListener : public ::testing::EmptyTestEventListener {
public:
  void OnTestStart(const ::testing::TestInfo&) override {
    const std::int64_t now = drainedTotal();
    if (now > m_mark)
      ADD_FAILURE() << now - m_mark << " GL error(s) before this test started (a test suite's set-up or the "
                    << "previous suite's teardown; docs/testing.md \"GL errors\"):" << messagesSince(m_mark);
    m_mark = now;
    g_excusedInTest = 0;
  }

  void OnTestEnd(const ::testing::TestInfo&) override {
    const std::int64_t now = drainedTotal();
    const std::int64_t undeclared = now - m_mark - g_excusedInTest;
    if (undeclared > 0)
      ADD_FAILURE() << undeclared << " GL error(s) in this test (set-up, upload, frames, read-back or teardown"
                    << "; declare deliberate ones with ExpectGlErrors; docs/testing.md \"GL errors\"):"
                    << messagesSince(m_mark);
    m_mark = now;
    g_excusedInTest = 0;
  }

  std::int64_t m_mark = glErrorTotal();
};

} // namespace

ExpectGlErrors::ExpectGlErrors(int count) : m_count(count), m_savedLevel(logLevel()) {
  m_mark = drainedTotal();
  setLogLevel(LogLevel::Quiet);
}

ExpectGlErrors::~ExpectGlErrors() {
  const std::int64_t made = drainedTotal() - m_mark;
  setLogLevel(m_savedLevel);
  EXPECT_EQ(made, m_count) << "GL errors made in an ExpectGlErrors scope:" << messagesSince(m_mark);
  g_excusedInTest += made;
  g_declaredInProcess += made;
  test::addDeliberateGlErrors(made);
}

void installGlErrorListener() {
  ::testing::UnitTest::GetInstance()->listeners().Append(new GlErrorListener);
}

bool noGlErrorsOutsideTests(const char* phase, std::int64_t mark) {
  const std::int64_t now = drainedTotal();
  if (now == mark) return true;
  std::printf("%lld GL error(s) in the render tests' %s (docs/testing.md \"GL errors\"):%s\n",
              static_cast<long long>(now - mark), phase, messagesSince(mark).c_str());
  return false;
}

void reportRenderTestGlErrors() {
  // Child processes' undeclared errors are added by the report itself.
  test::writeTestBinaryGlErrorReport("rtlab_render_tests", glErrorTotal() - g_declaredInProcess,
                                     glErrorMessagesSince(0));
}

} // namespace rtlab
