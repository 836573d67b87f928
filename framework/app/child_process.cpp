#include "app/child_process.h"

#include "util/error.h"

#include <sys/prctl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace rtlab {

pid_t spawnSelf(const ChildSpec& spec) {
  std::vector<char*> argv;
  for (const auto& a : spec.argv) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  std::vector<char*> envp;
  if (spec.environment) {
    for (const auto& e : *spec.environment) envp.push_back(const_cast<char*>(e.c_str()));
    envp.push_back(nullptr);
  }
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) throw Error(ExitCode::Internal, "cannot start " + spec.what + ": fork: " + std::strerror(errno));
  if (pid == 0) {
    if (spec.deathSignal != 0) ::prctl(PR_SET_PDEATHSIG, spec.deathSignal);
    if (::getppid() != parent) ::_exit(130); // the parent died before prctl
    if (spec.stdinFd >= 0) ::dup2(spec.stdinFd, 0);
    if (spec.stdoutFd >= 0) ::dup2(spec.stdoutFd, 1);
    if (spec.stderrFd >= 0) ::dup2(spec.stderrFd, 2);
    if (spec.environment) ::execve("/proc/self/exe", argv.data(), envp.data());
    else ::execv("/proc/self/exe", argv.data());
    ::_exit(127);
  }
  return pid;
}

} // namespace rtlab
