// A student's exercise folder (docs/exercises.md "The student's folder"): exercise.json naming the
// exercise and its files, the student's copy of each file at its repository path, and README.md.
#pragma once
#include "exercise/exercise_def.h"
#include "params/param_spec.h"

#include <map>
#include <string>
#include <vector>

namespace rtlab {

struct ExerciseFolder {
  std::string dir;
  const ExerciseDef* def = nullptr;
  std::vector<std::string> files; // as listed in exercise.json, relative to dir
};

// Reads DIR/exercise.json and checks that every file it lists is present. Error(Input) (exit 3)
// "DIR is not an exercise folder: ..." otherwise; an unknown exercise id is Error(Input) too.
ExerciseFolder readExerciseFolder(const std::string& dir);

// What `rtlab exercise new` writes, by path relative to the folder: exercise.json, the student's
// copy of each file (regions replaced by stubs) and README.md.
std::map<std::string, std::string> newExerciseFiles(const ExerciseDef& def, const std::vector<ParamSpec>& params);

// Shader replacements (gl::ShaderOverlay entries) by path relative to shaders/: the folder's files
// on disk, or the stubbed copies in memory.
struct ShaderFileReplacement {
  std::string shaderRelative; // "pcss/visibility.frag"
  std::string path;           // the file on disk, or a label for in-memory text
  std::string text;
  bool inMemory = false;
};
std::vector<ShaderFileReplacement> folderReplacements(const ExerciseFolder& folder);
std::vector<ShaderFileReplacement> stubReplacements(const ExerciseDef& def);

// The student's copy of one shipped file of `def` (its regions replaced by their stubs).
std::string stubbedFile(const ExerciseDef& def, const std::string& file);

} // namespace rtlab
