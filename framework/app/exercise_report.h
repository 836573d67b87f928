// The grade's HTML report (`rtlab exercise grade --report OUTDIR`, docs/exercises.md "Report"):
// OUTDIR/index.html with the score and one row per view, OUTDIR/<view>.html per view (student |
// solution | reference, the difference heat map, the figures and the likely cause), and
// OUTDIR/grade.json. Pages are self-contained (images embedded as PNG data URIs).
#pragma once
#include "app/exercise_grade.h"

#include <string>

namespace rtlab {

// Error(Output) unless OUTDIR is creatable, empty, or holds an earlier report (its grade.json):
// checked before grading so that no work is done in vain and nothing else is overwritten.
void checkReportFolder(const std::string& dir);

void writeGradeReport(const std::string& dir, const ExerciseFolder& folder, const GradeOptions& options,
                      const GradeResult& result);

} // namespace rtlab
