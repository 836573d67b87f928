// Runs a program with arguments, capturing stdout/stderr and the exit code, with a time limit.
#pragma once
#include <string>
#include <vector>

namespace rtlab::test {

struct ProcessResult {
  int exitCode = -1;    // -1 when killed by a signal or the time limit
  bool timedOut = false;
  std::string out, err;
  int glErrors = 0;     // the GL errors the process and its children reported (0 when none reported)
  std::string glReport; // their RTLAB_GL_ERRORS_FILE reports
};

// With interruptAfterMs >= 0 the process gets SIGINT that many milliseconds after it starts.
// The process runs with RTLAB_GL_ERRORS_FILE set to a file of its own (docs/contract.md
// "GL error report"): rtlab appends its GL error total there at exit. When the reports add up to
// another count than expectedGlErrors, the current test fails with the reports (docs/testing.md
// "GL errors"); errors beyond the expected ones count in the binary's total (gl_error_report.h).
ProcessResult runProcess(const std::string& program, const std::vector<std::string>& args, int timeoutSeconds = 60,
                         int interruptAfterMs = -1, int expectedGlErrors = 0);

// Number of non-empty lines.
int lineCount(const std::string& text);

} // namespace rtlab::test
