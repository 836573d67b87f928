// The grader's side of the worker processes (docs/exercises.md "Safety"): starts
// `rtlab exercise worker`, reads each view's result as it arrives, and enforces the per-view time
// limit. A worker that runs past the limit is killed and that view is a `timeout`; one that dies
// is a `crashed` view; either way a new worker goes on with the next view, so grading completes.
#pragma once
#include "app/exercise_worker.h"
#include "image/image.h"

#include <string>
#include <vector>

namespace rtlab {

enum class ViewRunStatus { Ok, CompileError, Error, Timeout, Crashed };

struct ViewRun {
  ViewRunStatus status = ViewRunStatus::Error;
  std::string message; // compile errors name file:line; crashes the worker's last stderr line
  int code = 0;        // the Error's exit code for Error and CompileError
  double ms = 0.0;
  Image image;
  Image reference;     // when the request asked for references
  std::string driver;  // the worker's GL driver when it rendered (driverName)
};

// Runs the request's views (all of them; request.first is ignored) in workers, `timeLimitSeconds`
// per view (the first view's limit also covers starting the worker and compiling).
std::vector<ViewRun> runViewsInWorkers(WorkerRequest request, double timeLimitSeconds);

} // namespace rtlab
