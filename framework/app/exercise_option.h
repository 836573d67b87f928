// `--exercise DIR` on render and view (docs/contract.md "Exercises"): the student's files replace
// the shipped ones for this process, and the exercise's technique is active unless -t was given.
#pragma once
#include "app/args.h"
#include "app/frame_options.h"
#include "exercise/exercise_def.h"
#include "exercise/exercise_folder.h"
#include "params/param_spec.h"

#include <vector>

namespace rtlab {

OptionSpec exerciseOptionSpec();

// With --exercise DIR: reads the folder (Error(Input), exit 3, when it is not an exercise folder),
// installs its files in place of the shipped shaders, and activates the exercise's technique when
// the command line has no -t. Returns "exercise ID (DIR)" for titles, or "" without --exercise.
// Call before any program is built.
std::string applyExerciseOption(const Args& args, ResolvedFrame& frame);

// Puts the files in place of the shipped shaders for this process (gl::setShaderOverlay).
void installShaderReplacements(const std::vector<ShaderFileReplacement>& files);

// The parameters an assignment lists: the technique's own, then its stage's.
std::vector<ParamSpec> exerciseParams(const ExerciseDef& def);

} // namespace rtlab
