// `rtlab sweep` as a function, for commands built on sweeps (the showcase's atlas): runs the
// command line `rtlab sweep ARGS...` exactly as the binary would (planning, the folder rule,
// the jobs as child processes, --collect) and returns what was collected.
#pragma once
#include "app/sweep_collect.h"

#include <string>
#include <vector>

namespace rtlab {

// `args` without "rtlab sweep"; a direct sweep (no --emit-jobs, no --collect). Throws Error as
// the command would exit.
SweepCollection runSweepCommand(const std::vector<std::string>& args);

} // namespace rtlab
