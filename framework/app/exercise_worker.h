// The grader's worker process (docs/exercises.md "Safety"): `rtlab exercise worker`, started by
// `rtlab exercise grade`, never by users. It reads one request as JSON on stdin, renders the views
// in order in one GL context with the requested files in place of the shipped shaders, and streams
// each result to stdout: a JSON header line, then the raw floats of the image (and its mask, and
// for the solution the reference). It writes no file.
#pragma once
#include "app/frame_options.h"
#include "exercise/exercise_def.h"
#include "image/image.h"
#include "platform/context.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace rtlab {

enum class WorkerFiles { Solution, Stub, Student };

struct WorkerRequest {
  std::string exercise;
  WorkerFiles files = WorkerFiles::Solution;
  std::string dir;                 // the student's folder (Student)
  std::string aov;
  std::string backend = "auto";
  bool references = false;         // also render each view's reference (Solution)
  std::vector<ExerciseView> views;
  std::size_t first = 0;           // the first view to render (after a restart)
};

nlohmann::json workerRequestJson(const WorkerRequest& request);
WorkerRequest workerRequestFromJson(const nlohmann::json& j);

// One view as a resolved frame: its scene and frame options go through the command line's parser,
// so a bad key or value is the same Error(Usage) as on the command line.
// "backend | vendor | renderer | version" of a context: renders on another driver may differ.
std::string driverName(const Context& context);

ResolvedFrame resolveViewFrame(const ExerciseView& view, const std::string& technique, const std::string& backend);

// The result header of one view: {"view": i, "status": "ok"|"compile_error"|"error", "message",
// "ms", "image": [w, h, channels, mask], "reference": [w, h, channels, mask] (when sent), "gl": the
// driver that rendered it (driverName; the grade cache's key, app/exercise_grade_cache.h)}.
int runExerciseWorker();

} // namespace rtlab
