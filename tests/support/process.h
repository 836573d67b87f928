// Runs a program with arguments, capturing stdout/stderr and the exit code, with a time limit.
#pragma once
#include <string>
#include <vector>

namespace rtlab::test {

struct ProcessResult {
  int exitCode = -1;    // -1 when killed by a signal or the time limit
  bool timedOut = false;
  std::string out, err;
};

// With interruptAfterMs >= 0 the process gets SIGINT that many milliseconds after it starts.
ProcessResult runProcess(const std::string& program, const std::vector<std::string>& args, int timeoutSeconds = 60,
                         int interruptAfterMs = -1);

// Number of non-empty lines.
int lineCount(const std::string& text);

} // namespace rtlab::test
