#include "process.h"

#include "gl_error_report.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

namespace rtlab::test {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// This process's environment with RTLAB_GL_ERRORS_FILE=`reportPath` (built before fork: the child
// only calls async-signal-safe functions).
std::vector<std::string> childEnvironment(const std::string& reportPath) {
  static const char kName[] = "RTLAB_GL_ERRORS_FILE=";
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, kName, sizeof kName - 1) != 0) env.emplace_back(*e);
  env.push_back(kName + reportPath);
  return env;
}

// The child's GL error reports against what the test expected.
void checkGlErrors(const std::string& program, const std::vector<std::string>& args, ProcessResult& r,
                   int expected) {
  const std::int64_t reported = std::max<std::int64_t>(parseGlErrorReport(r.glReport), 0);
  r.glErrors = static_cast<int>(reported);
  addDeliberateGlErrors(std::min<std::int64_t>(reported, expected));
  addChildGlErrors(std::max<std::int64_t>(reported - expected, 0));
  if (reported == expected) return;
  std::string command = program;
  for (const auto& a : args) command += " " + a;
  ADD_FAILURE() << "GL errors reported by '" << command << "': " << reported << ", expected " << expected
                << " (docs/testing.md \"GL errors\"):\n" << r.glReport;
}

} // namespace

ProcessResult runProcess(const std::string& program, const std::vector<std::string>& args, int timeoutSeconds,
                         int interruptAfterMs, int expectedGlErrors) {
  char outTemplate[] = "/tmp/rtlab-test-out-XXXXXX";
  char errTemplate[] = "/tmp/rtlab-test-err-XXXXXX";
  char glTemplate[] = "/tmp/rtlab-test-gl-XXXXXX";
  const int outFd = mkstemp(outTemplate);
  const int errFd = mkstemp(errTemplate);
  const int glFd = mkstemp(glTemplate);
  close(glFd);
  const std::vector<std::string> env = childEnvironment(glTemplate);
  std::vector<char*> envp;
  for (const auto& e : env) envp.push_back(const_cast<char*>(e.c_str()));
  envp.push_back(nullptr);
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(program.c_str()));
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  ProcessResult r;
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(outFd, 1);
    dup2(errFd, 2);
    execve(program.c_str(), argv.data(), envp.data());
    _exit(127);
  }
  int status = 0;
  const auto start = std::chrono::steady_clock::now();
  bool interrupted = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
  while (true) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (interruptAfterMs >= 0 && !interrupted &&
        std::chrono::steady_clock::now() - start > std::chrono::milliseconds(interruptAfterMs)) {
      kill(pid, SIGINT);
      interrupted = true;
    }
    if (std::chrono::steady_clock::now() > deadline) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      r.timedOut = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (!r.timedOut && WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
  close(outFd);
  close(errFd);
  r.out = slurp(outTemplate);
  r.err = slurp(errTemplate);
  r.glReport = slurp(glTemplate);
  std::remove(outTemplate);
  std::remove(errTemplate);
  std::remove(glTemplate);
  checkGlErrors(program, args, r, expectedGlErrors);
  return r;
}

int lineCount(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  int n = 0;
  while (std::getline(in, line))
    if (!line.empty()) ++n;
  return n;
}

} // namespace rtlab::test
