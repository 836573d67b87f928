// The assignment a student gets with `rtlab exercise new` (README.md in the folder): the
// exercise's background, each region's task with its file and line, the technique's parameters,
// how to run and view the student's version, and how it is graded (the views that are not hidden).
#pragma once
#include "exercise/exercise_def.h"
#include "params/param_spec.h"

#include <string>
#include <vector>

namespace rtlab {

// `params`: the parameters worth listing (the technique's own and its stage's).
std::string assignmentMarkdown(const ExerciseDef& def, const std::vector<ParamSpec>& params);

} // namespace rtlab
