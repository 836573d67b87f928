// Child processes of this binary (`/proc/self/exe`): sweep jobs (docs/sweeps.md "Jobs") and the
// grader's workers (docs/exercises.md "Safety"). Everything the child needs is prepared before
// fork; between fork and exec it only calls async-signal-safe functions.
#pragma once
#include <sys/types.h>

#include <string>
#include <vector>

namespace rtlab {

struct ChildSpec {
  std::vector<std::string> argv;        // argv[0] included
  int stdinFd = -1, stdoutFd = -1, stderrFd = -1; // put on 0, 1, 2 in the child (-1: inherited)
  int deathSignal = 0;                  // sent to the child when this process dies (PR_SET_PDEATHSIG)
  const std::vector<std::string>* environment = nullptr; // "NAME=value" list; nullptr: inherited
  std::string what;                     // "a sweep job": names it in the fork error
};

// Starts the child; Error(Internal) "cannot start <what>: fork: ..." when fork fails.
pid_t spawnSelf(const ChildSpec& spec);

} // namespace rtlab
