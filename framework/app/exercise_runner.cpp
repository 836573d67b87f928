#include "app/exercise_runner.h"

#include "app/child_process.h"
#include "image/raw_image.h"
#include "util/error.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cerrno>
#include <cstring>

extern char** environ;

namespace rtlab {
namespace {

using Clock = std::chrono::steady_clock;

// Environment of a worker: the parent's, with every shader disk cache off, so that grading writes
// nothing outside the output folder (Mesa and NVIDIA would otherwise cache the student's shaders).
std::vector<std::string> workerEnvironment() {
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e) {
    const std::string var = *e;
    if (var.rfind("MESA_SHADER_CACHE_DISABLE=", 0) == 0 || var.rfind("MESA_DISK_CACHE", 0) == 0 ||
        var.rfind("__GL_SHADER_DISK_CACHE=", 0) == 0)
      continue;
    env.push_back(var);
  }
  env.push_back("MESA_SHADER_CACHE_DISABLE=true");
  env.push_back("__GL_SHADER_DISK_CACHE=0");
  return env;
}

struct Worker {
  pid_t pid = -1;
  int out = -1; // its stdout
  int err = -1; // its stderr
};

void closeFd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

Worker startWorker(const std::string& request) {
  int in[2], out[2], err[2];
  if (::pipe2(in, O_CLOEXEC) != 0 || ::pipe2(out, O_CLOEXEC) != 0 || ::pipe2(err, O_CLOEXEC) != 0)
    throw Error(ExitCode::Internal, std::string("cannot start a grading worker: pipe: ") + std::strerror(errno));
  const std::vector<std::string> env = workerEnvironment();
  // A killed grader takes its worker with it.
  const ChildSpec spec{{"rtlab", "exercise", "worker"}, in[0], out[1], err[1], SIGKILL, &env, "a grading worker"};
  pid_t pid = -1;
  try {
    pid = spawnSelf(spec);
  } catch (...) {
    for (int fd : {in[0], in[1], out[0], out[1], err[0], err[1]}) ::close(fd);
    throw;
  }
  ::close(in[0]);
  ::close(out[1]);
  ::close(err[1]);
  // The request is small (well under a pipe's buffer): write it and close, so the worker sees EOF.
  std::size_t written = 0;
  while (written < request.size()) {
    const ssize_t n = ::write(in[1], request.data() + written, request.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    written += std::size_t(n);
  }
  ::close(in[1]);
  return Worker{pid, out[0], err[0]};
}

// Parses complete results at the front of `buffer` into `runs`; returns how many it took.
std::size_t takeResults(std::string& buffer, std::vector<ViewRun>& runs, std::vector<bool>& done) {
  std::size_t taken = 0;
  for (;;) {
    const std::size_t eol = buffer.find('\n');
    if (eol == std::string::npos) return taken;
    const nlohmann::json header = nlohmann::json::parse(buffer.substr(0, eol));
    std::size_t need = eol + 1;
    if (header.contains("image")) need += rawImageBytes(header["image"]);
    if (header.contains("reference")) need += rawImageBytes(header["reference"]);
    if (buffer.size() < need) return taken;
    const std::size_t i = header.at("view").get<std::size_t>();
    ViewRun& run = runs.at(i);
    const std::string status = header.at("status").get<std::string>();
    run.status = status == "ok" ? ViewRunStatus::Ok : status == "compile_error" ? ViewRunStatus::CompileError : ViewRunStatus::Error;
    run.message = header.value("message", "");
    run.ms = header.value("ms", 0.0);
    run.code = header.value("code", 0);
    run.driver = header.value("gl", "");
    std::size_t at = eol + 1;
    if (header.contains("image")) {
      run.image = rawImageFrom(header["image"], buffer.data() + at);
      at += rawImageBytes(header["image"]);
    }
    if (header.contains("reference")) run.reference = rawImageFrom(header["reference"], buffer.data() + at);
    done.at(i) = true;
    buffer.erase(0, need);
    ++taken;
  }
}

std::string lastLine(const std::string& text) {
  std::size_t end = text.find_last_not_of("\n ");
  if (end == std::string::npos) return "";
  const std::size_t begin = text.rfind('\n', end);
  return text.substr(begin == std::string::npos ? 0 : begin + 1, end - (begin == std::string::npos ? 0 : begin + 1) + 1);
}

std::string describeExit(int status) {
  if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
  if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
  return "ended";
}

} // namespace

std::vector<ViewRun> runViewsInWorkers(WorkerRequest request, double timeLimitSeconds) {
  std::vector<ViewRun> runs(request.views.size());
  std::vector<bool> done(request.views.size(), false);
  std::size_t next = 0;
  const auto limit = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeLimitSeconds));
  while (next < request.views.size()) {
    request.first = next;
    Worker worker = startWorker(workerRequestJson(request).dump());
    std::string buffer, errText;
    auto deadline = Clock::now() + limit;
    bool timedOut = false;
    while (worker.out >= 0) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) {
        timedOut = true;
        break;
      }
      pollfd fds[2] = {{worker.out, POLLIN, 0}, {worker.err, POLLIN, 0}};
      const int n = ::poll(fds, worker.err >= 0 ? 2 : 1, int(std::min<long long>(left, 1000)));
      if (n < 0 && errno == EINTR) continue;
      char chunk[65536];
      if (worker.err >= 0 && (fds[1].revents & (POLLIN | POLLHUP))) {
        const ssize_t got = ::read(worker.err, chunk, sizeof(chunk));
        if (got <= 0) closeFd(worker.err);
        else if (errText.size() < 65536) errText.append(chunk, std::size_t(got));
      }
      if (fds[0].revents & (POLLIN | POLLHUP)) {
        const ssize_t got = ::read(worker.out, chunk, sizeof(chunk));
        if (got <= 0) {
          closeFd(worker.out);
        } else {
          buffer.append(chunk, std::size_t(got));
          if (takeResults(buffer, runs, done) > 0) {
            while (next < done.size() && done[next]) ++next;
            deadline = Clock::now() + limit;
          }
        }
      }
    }
    if (timedOut) ::kill(worker.pid, SIGKILL);
    int status = 0;
    while (::waitpid(worker.pid, &status, 0) < 0 && errno == EINTR) {
    }
    closeFd(worker.out);
    closeFd(worker.err);
    if (next >= runs.size()) break;
    ViewRun& run = runs[next];
    if (timedOut) {
      run.status = ViewRunStatus::Timeout;
      run.message = "ran past the time limit of " + std::to_string(int(timeLimitSeconds + 0.5)) + " s";
      run.ms = timeLimitSeconds * 1000.0;
    } else {
      run.status = ViewRunStatus::Crashed;
      const std::string why = lastLine(errText);
      run.message = "the render process " + describeExit(status) + (why.empty() ? "" : ": " + why);
    }
    done[next] = true;
    while (next < done.size() && done[next]) ++next;
  }
  return runs;
}

} // namespace rtlab
