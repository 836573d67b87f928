// `rtlab exercise grade` (docs/exercises.md "Grading"): renders the views with the student's files,
// the solution's and the stubs' in worker processes, compares each with the solution (tolerant) and
// with the reference (informative), and gives the per-view status, cause and the score.
#pragma once
#include "exercise/exercise_folder.h"
#include "exercise/grade_cache.h"
#include "exercise/view_compare.h"
#include "image/image.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace rtlab {

struct GradeOptions {
  std::vector<ExerciseView> views;
  ExerciseTolerance tolerance;
  double timeLimitSeconds = 30.0;
  std::string backend = "auto";
  bool keepImages = false;  // keep the images for the report
  bool progress = false;    // a line per phase on stderr
  const GradeCache* cache = nullptr; // --cache: the solution's and stubs' renders (docs/exercises.md "The grade cache")
};

struct ViewGrade {
  std::string name;
  std::string status;       // passed | failed | timeout | crashed | compile_error
  std::string cause;        // empty when passed
  bool passed = false;
  std::optional<double> rmseVsSolution, differingFraction, rmseVsReference;
  std::optional<double> rmseAgreeing; // over the pixels that do not differ (the bound's figure)
  double solutionRmseVsReference = 0.0;
  double ms = 0.0;          // the student's render of the view (wall time, including compiling on the first)
  // With keepImages:
  Image student, solution, reference;
  bool hasStudent = false;
};

struct GradeResult {
  std::string exercise;
  std::vector<ViewGrade> views;
  int score = 0;
  bool passed = false;
  std::string compileError; // the first compile error (file:line), empty without one
};

GradeResult gradeExercise(const ExerciseFolder& folder, const GradeOptions& options);

// {"schema": 1, "exercise", "passed", "score", "views": [...]} (docs/contract.md "Exercises").
nlohmann::ordered_json gradeJson(const GradeResult& result);

} // namespace rtlab
