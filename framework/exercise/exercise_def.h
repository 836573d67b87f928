// Exercise definitions (docs/exercises.md "Definitions"): assets/exercises/<id>.json names the
// technique, the regions a student writes, the AOV graded, the tolerances and the test views. The
// files of an exercise are the shipped shaders that hold its regions.
#pragma once
#include <nlohmann/json_fwd.hpp>

#include <string>
#include <utility>
#include <vector>

namespace rtlab {

struct ExerciseView {
  std::string name;
  std::string scene;
  int width = 160, height = 90;
  std::vector<std::pair<std::string, std::string>> set; // --set KEY=VALUE, in order
  std::vector<std::string> techniques;                   // empty: the exercise's technique
  unsigned seed = 1;
  int spp = 0;                                           // reference samples per pixel; 0: its default
  bool hidden = false;                                   // not listed in the student's README
  std::string note;                                      // what the view tests
};

// A pixel differs when |student - solution| > pixel in any channel; a view passes when at most
// `fraction` of the valid pixels differ and the RMSE over the other valid pixels (those that do not
// differ) is at most `rmse`: the fraction bounds a few flipped pixels at shadow edges, the RMSE a
// small error everywhere (docs/exercises.md "Tolerances").
struct ExerciseTolerance {
  double pixel = 0.02;
  double fraction = 0.005;
  double rmse = 0.01;
};

struct ExerciseDef {
  std::string id;
  std::string technique;
  std::string title;
  std::string aov;
  std::vector<std::string> regions;
  std::vector<std::string> background; // markdown paragraphs of the assignment
  ExerciseTolerance tolerance;
  double timeLimitSeconds = 30.0;      // per view, for the student's render
  std::vector<ExerciseView> views;
  std::vector<std::string> files;      // repository-relative ("shaders/pcss/visibility.frag")
  std::string source;                  // the definition file
};

struct ExerciseViews {
  std::vector<ExerciseView> views;
  bool hasTolerance = false;
  ExerciseTolerance tolerance;
};

// Every definition under assets/exercises/, sorted by id, with its files resolved from the
// regions in shaders/. A malformed definition or region, an unknown region or a region in two
// files is Error(Input) naming the file.
const std::vector<ExerciseDef>& exerciseCatalog();
// Error(Usage) "unknown exercise 'x'" with the known ids.
const ExerciseDef& findExercise(const std::string& id);

// Parses a definition's text (`source` names it in errors).
ExerciseDef parseExerciseDef(const std::string& text, const std::string& source);
// A course author's views (`--views FILE`): {"schema": 1, "views": [...], "tolerance": {...}}.
ExerciseViews readExerciseViews(const std::string& path);

// Views as the definitions write them, and back (for the grader's worker processes).
nlohmann::json viewsToJson(const std::vector<ExerciseView>& views);
std::vector<ExerciseView> viewsFromJson(const nlohmann::json& views, const std::string& source);
// "160x90"
std::string viewSize(const ExerciseView& view);

// The shipped shader files (repository-relative) that hold each region, from shaders/.
struct RegionLocation {
  std::string region;
  std::string file;
};
std::vector<RegionLocation> shippedRegions();

} // namespace rtlab
