// Every GL error in the render-test binary fails the test it happened in (docs/testing.md "GL
// errors"): a gtest listener compares the process total (glErrorTotal) before and after each test,
// so set-up, upload, frames, read-back and teardown all count, not only the frames.
#pragma once
#include <cstdint>

#include "util/log.h"

namespace rtlab {

// Declares that the enclosing scope makes exactly `count` GL errors on purpose. The destructor
// checks the count (a test failure, with the messages, when it differs) and excuses those errors
// from the listener's check and from the binary's total. The log is quiet meanwhile (the errors
// would be logged as warnings).
class ExpectGlErrors {
public:
  explicit ExpectGlErrors(int count);
  ~ExpectGlErrors();
  ExpectGlErrors(const ExpectGlErrors&) = delete;
  ExpectGlErrors& operator=(const ExpectGlErrors&) = delete;

private:
  int m_count;
  std::int64_t m_mark;
  LogLevel m_savedLevel;
};

// Appends the per-test listener to gtest's listeners (after InitGoogleTest, before RUN_ALL_TESTS).
void installGlErrorListener();

// Errors since `mark` outside any test (the binary's global set-up or teardown, named by `phase`):
// printed with their messages; returns false when there are any.
bool noGlErrorsOutsideTests(const char* phase, std::int64_t mark);

// The binary's report at its end (tests/support/gl_error_report.h): the errors nobody declared.
void reportRenderTestGlErrors();

} // namespace rtlab
