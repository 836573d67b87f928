// How a student's view is judged against the solution's (docs/exercises.md "Grading"): a tolerant
// comparison over the valid pixels (the solution's mask), and the likely cause of a failure where
// it can be recognised (the stub left in place, an inverted result, NaN/Inf pixels, a constant).
#pragma once
#include "exercise/exercise_def.h"
#include "image/image.h"

#include <cstddef>
#include <string>

namespace rtlab {

struct ViewComparison {
  bool passed = false;
  double rmseVsSolution = 0.0;      // over valid pixels where both are finite
  double rmseAgreeing = 0.0;        // the same over the pixels that do not differ (the small-error bound)
  double differingFraction = 0.0;   // of valid pixels: differ by more than the pixel tolerance, or not finite
  std::size_t nonFinite = 0;        // valid pixels where the student's value is NaN or Inf
  double meanSignedDifference = 0.0; // student - solution, over valid finite pixels
  std::string cause;                // empty when passed
};

// `stub`: the same view rendered with the exercise's stubs (nullptr when not available). Images of
// different sizes or channel counts: Error(Input).
ViewComparison compareWithSolution(const Image& student, const Image& solution, const Image* stub,
                                   const ExerciseTolerance& tolerance);

} // namespace rtlab
