// rtlab exercise list | new ID --out DIR | grade DIR (docs/contract.md "Exercises",
// docs/exercises.md).
#include "app/args.h"
#include "app/commands.h"
#include "app/exercise_grade.h"
#include "app/exercise_option.h"
#include "app/exercise_report.h"
#include "app/exercise_worker.h"
#include "app/frame_options.h"
#include "exercise/assignment.h"
#include "exercise/exercise_folder.h"
#include "frame/aovs.h"
#include "frame/registry.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/number_format.h"

#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <optional>

namespace rtlab {
namespace fs = std::filesystem;
namespace {

const char* kUsage = "rtlab exercise list [--json] | new ID --out DIR | grade DIR [--json] [--report OUTDIR] [--views FILE]\n"
                     "                      [--time-limit S] [--backend auto|egl|osmesa] [--cache CACHEDIR]";

int runExerciseList(int argc, char** argv) {
  const std::vector<OptionSpec> specs = {{"--json", "", false, "", "print JSON (docs/contract.md)"}};
  Args args("exercise list", specs, argc, argv, 3);
  if (args.help()) {
    std::cout << formatHelp("rtlab exercise list [--json]", "Lists the exercises: id, technique, title and files.", specs);
    return 0;
  }
  const auto& catalog = exerciseCatalog();
  if (args.has("--json")) {
    nlohmann::ordered_json j;
    j["schema"] = 1;
    j["exercises"] = nlohmann::ordered_json::array();
    for (const auto& def : catalog)
      j["exercises"].push_back({{"id", def.id}, {"technique", def.technique}, {"title", def.title}, {"files", def.files}});
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  for (const auto& def : catalog) {
    std::cout << def.id << "  (" << def.technique << ")  " << def.title << "\n";
    for (const auto& f : def.files) std::cout << "    " << f << "\n";
  }
  return 0;
}

int runExerciseNew(int argc, char** argv) {
  const std::vector<OptionSpec> specs = {{"--out", "", true, "DIR", "the student's folder to create (must not exist or be empty)"}};
  Args args("exercise new", specs, argc, argv, 3, 1);
  if (args.help()) {
    std::cout << formatHelp("rtlab exercise new ID --out DIR",
                            "Writes a student's folder: exercise.json, the exercise's files with each region replaced\n"
                            "by a stub that compiles and returns a neutral value, and README.md (the assignment).", specs);
    return 0;
  }
  if (args.positionals().size() != 1) usageError("exercise new needs an exercise id (see 'rtlab exercise list')");
  const std::string dir = args.get("--out");
  if (dir.empty()) usageError("exercise new needs --out DIR");
  const ExerciseDef& def = findExercise(args.positionals()[0]);
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) outputError("--out " + dir + " exists and is not a directory");
  if (fs::is_directory(dir, ec) && !fs::is_empty(dir, ec))
    outputError("--out " + dir + " is not empty; exercise new never overwrites anything: choose a new folder");
  const auto files = newExerciseFiles(def, exerciseParams(def));
  const bool existed = fs::exists(dir, ec);
  try {
    for (const auto& [rel, text] : files) {
      const fs::path path = fs::path(dir) / rel;
      fs::create_directories(path.parent_path(), ec);
      if (ec) outputError("cannot create " + path.parent_path().string() + ": " + ec.message());
      writeTextAtomically(path.string(), text);
    }
  } catch (...) {
    // Nothing half-written: remove what this command made.
    if (existed) {
      for (const auto& entry : fs::directory_iterator(dir, ec)) fs::remove_all(entry.path(), ec);
    } else {
      fs::remove_all(dir, ec);
    }
    throw;
  }
  std::cout << "exercise '" << def.id << "' written to " << dir << ": README.md has the assignment; edit";
  for (const auto& f : def.files) std::cout << " " << f;
  std::cout << "\n";
  return 0;
}

int runExerciseGrade(int argc, char** argv) {
  const std::vector<OptionSpec> specs = {
      {"--json", "", false, "", "print the grade as JSON (docs/contract.md)"},
      {"--report", "", true, "OUTDIR", "write index.html, a page per view and grade.json into OUTDIR"},
      {"--views", "", true, "FILE", "grade these views ({\"schema\": 1, \"views\": [...]}) instead of the exercise's"},
      {"--time-limit", "", true, "S", "seconds each view of the student's may take (default: the exercise's)"},
      {"--backend", "", true, "B", "headless context of the renders: auto, egl or osmesa (default auto)"},
      {"--cache", "", true, "CACHEDIR", "keep the solution's and the stubs' renders in CACHEDIR and reuse them (created if missing)"}};
  Args args("exercise grade", specs, argc, argv, 3, 1);
  if (args.help()) {
    std::cout << formatHelp("rtlab exercise grade DIR [--json] [--report OUTDIR] [--views FILE] [--time-limit S] [--cache CACHEDIR]",
                            "Renders the exercise's test views with DIR's files, the solution's and the stubs' (each in\n"
                            "a child process with a time limit), compares each view with the solution and the reference,\n"
                            "and prints the score. Exit 0 when grading completed, passed or not; 5 when a student file\n"
                            "does not compile (the JSON is still written); 3 when DIR is not an exercise folder; 6 when\n"
                            "the --report or --cache folder cannot be used.", specs);
    return 0;
  }
  if (args.positionals().size() != 1) usageError("exercise grade needs the student's folder");
  const ExerciseFolder folder = readExerciseFolder(args.positionals()[0]);
  const ExerciseDef& def = *folder.def;

  GradeOptions options;
  options.views = def.views;
  options.tolerance = def.tolerance;
  options.timeLimitSeconds = def.timeLimitSeconds;
  if (args.has("--views")) {
    const ExerciseViews custom = readExerciseViews(args.get("--views"));
    options.views = custom.views;
    if (custom.hasTolerance) options.tolerance = custom.tolerance;
  }
  if (args.has("--time-limit")) {
    options.timeLimitSeconds = parsePositiveNumber("--time-limit", args.get("--time-limit"));
    if (options.timeLimitSeconds > 3600) usageError("--time-limit must be in (0, 3600] seconds");
  }
  if (args.has("--backend")) {
    options.backend = args.get("--backend");
    parseBackend(options.backend); // Error(Usage) for an unknown one
  }
  // Every view must be a valid frame with the exercise's AOV before anything renders.
  for (const auto& view : options.views) {
    try {
      const ResolvedFrame frame = resolveViewFrame(view, def.technique, options.backend);
      checkAovName(def.aov, frame.techniques, TechniqueRegistry::instance());
    } catch (const Error& e) {
      throw Error(e.code(), "view '" + view.name + "': " + e.what());
    }
  }
  const std::string report = args.get("--report");
  if (args.has("--report")) {
    if (report.empty()) usageError("--report needs a folder");
    checkReportFolder(report);
  }
  options.keepImages = !report.empty();
  // With a cache, the phase lines say what came from it (docs/exercises.md "The grade cache").
  std::optional<GradeCache> cache;
  if (args.has("--cache")) {
    if (args.get("--cache").empty()) usageError("--cache needs a folder");
    cache.emplace(args.get("--cache"));
    options.cache = &*cache;
  }
  options.progress = ::isatty(STDERR_FILENO) == 1 || cache;

  const GradeResult result = gradeExercise(folder, options);
  if (!report.empty()) writeGradeReport(report, folder, options, result);
  if (args.has("--json")) {
    std::cout << gradeJson(result).dump(2) << "\n";
  } else {
    for (const auto& v : result.views)
      std::cout << v.name << ": " << v.status << (v.cause.empty() ? "" : " (" + v.cause + ")") << "\n";
    std::cout << "score " << result.score << " (" << (result.passed ? "passed" : "not passed") << ")\n";
  }
  std::cout.flush();
  if (!result.compileError.empty()) throw Error(ExitCode::Shader, result.compileError);
  return 0;
}

} // namespace

int runExercise(int argc, char** argv) {
  const std::string sub = argc > 2 ? argv[2] : "";
  if (sub == "list") return runExerciseList(argc, argv);
  if (sub == "new") return runExerciseNew(argc, argv);
  if (sub == "grade") return runExerciseGrade(argc, argv);
  if (sub == "worker") return runExerciseWorker();
  if (sub == "--help" || sub == "-h") {
    std::cout << "Usage: " << kUsage << "\n\nCourse exercises: list them, make a student's folder, grade one "
                 "(docs/exercises.md).\n'rtlab exercise <list|new|grade> --help' describes each.\n";
    return 0;
  }
  usageError(sub.empty() ? std::string("exercise needs a subcommand: list, new or grade")
                         : "unknown exercise subcommand '" + sub + "' (list, new, grade)");
}

} // namespace rtlab
