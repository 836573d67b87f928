#include "exercise/view_compare.h"

#include "util/error.h"
#include "util/number_format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace rtlab {
namespace {

bool valid(const Image& solution, std::size_t pixel) { return !solution.hasMask() || solution.mask[pixel] > 0.5f; }

struct Difference {
  double rmse = 0.0;          // over the valid finite pixels
  double rmseAgreeing = 0.0;  // over the valid finite pixels within the per-pixel tolerance
  double fraction = 0.0;
  double meanSigned = 0.0;
  std::size_t darker = 0, brighter = 0; // differing pixels below / above the other image
  std::size_t nonFinite = 0;
  std::size_t validPixels = 0;
};

// a against b over b's valid pixels; `invertA` compares 1 - a instead (an inverted result).
Difference difference(const Image& a, const Image& b, double pixelTolerance, bool invertA = false) {
  Difference d;
  double sumSq = 0.0, sumSigned = 0.0, sumSqAgreeing = 0.0;
  std::size_t finite = 0, differing = 0, agreeing = 0;
  const int c = b.channels;
  for (std::size_t p = 0; p < b.pixelCount(); ++p) {
    if (!valid(b, p)) continue;
    ++d.validPixels;
    bool finitePixel = true, differs = false;
    double pixelSq = 0.0, pixelSigned = 0.0, worst = 0.0;
    for (int k = 0; k < c; ++k) {
      double va = a.pixels[p * c + k];
      const double vb = b.pixels[p * c + k];
      if (!std::isfinite(va) || !std::isfinite(vb)) {
        finitePixel = false;
        continue;
      }
      if (invertA) va = 1.0 - va;
      const double diff = va - vb;
      pixelSq += diff * diff;
      pixelSigned += diff;
      if (std::abs(diff) > pixelTolerance) {
        differs = true;
        if (std::abs(diff) > std::abs(worst)) worst = diff;
      }
    }
    if (!finitePixel) {
      ++d.nonFinite;
      ++differing;
      continue;
    }
    ++finite;
    sumSq += pixelSq / c;
    sumSigned += pixelSigned / c;
    differing += differs ? 1 : 0;
    if (!differs) {
      ++agreeing;
      sumSqAgreeing += pixelSq / c;
    }
    d.darker += worst < 0.0 ? 1 : 0;
    d.brighter += worst > 0.0 ? 1 : 0;
  }
  if (finite > 0) {
    d.rmse = std::sqrt(sumSq / double(finite));
    if (agreeing > 0) d.rmseAgreeing = std::sqrt(sumSqAgreeing / double(agreeing));
    d.meanSigned = sumSigned / double(finite);
  }
  if (d.validPixels > 0) d.fraction = double(differing) / double(d.validPixels);
  return d;
}

bool withinTolerance(const Difference& d, const ExerciseTolerance& t) {
  return d.nonFinite == 0 && d.fraction <= t.fraction && d.rmseAgreeing <= t.rmse;
}

// True when every valid, finite pixel of `image` holds the same value (within 1e-6).
bool constantOver(const Image& image, const Image& validity, float& value) {
  bool first = true;
  for (std::size_t p = 0; p < image.pixelCount(); ++p) {
    if (!valid(validity, p)) continue;
    for (int k = 0; k < image.channels; ++k) {
      const float v = image.pixels[p * image.channels + k];
      if (!std::isfinite(v)) continue;
      if (first) {
        value = v;
        first = false;
      } else if (std::abs(v - value) > 1e-6f) {
        return false;
      }
    }
  }
  return !first;
}

std::string fixed(double value, const char* format) {
  char text[64];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}
std::string percent(double fraction) { return fixed(fraction * 100.0, "%.2g%%"); }
std::string short3(double value) { return fixed(value, "%.3g"); }

// The smallest and largest finite value over the valid pixels of `validity`.
void finiteRange(const Image& image, const Image& validity, float& lo, float& hi) {
  lo = std::numeric_limits<float>::infinity();
  hi = -lo;
  for (std::size_t p = 0; p < image.pixelCount(); ++p) {
    if (!valid(validity, p)) continue;
    for (int k = 0; k < image.channels; ++k) {
      const float v = image.pixels[p * image.channels + k];
      if (!std::isfinite(v)) continue;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
}

} // namespace

ViewComparison compareWithSolution(const Image& student, const Image& solution, const Image* stub,
                                   const ExerciseTolerance& tolerance) {
  auto sameShape = [](const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.channels == b.channels;
  };
  if (!sameShape(student, solution) || (stub && !sameShape(*stub, solution)))
    inputError("the student's image and the solution's differ in size or channels");
  const Difference d = difference(student, solution, tolerance.pixel);
  ViewComparison out;
  out.rmseVsSolution = d.rmse;
  out.rmseAgreeing = d.rmseAgreeing;
  out.differingFraction = d.fraction;
  out.nonFinite = d.nonFinite;
  out.meanSignedDifference = d.meanSigned;
  out.passed = withinTolerance(d, tolerance);
  if (out.passed) return out;

  if (d.nonFinite > 0) {
    out.cause = "nan: " + std::to_string(d.nonFinite) +
                " pixels are NaN or Inf (a division by zero, or sqrt/log of a negative, at this view's settings)";
    return out;
  }
  if (stub && withinTolerance(difference(student, *stub, tolerance.pixel), tolerance)) {
    out.cause = "stub: the output is the stub's neutral value (the region still holds the stub, or the code "
                "has no effect on the result)";
    return out;
  }
  if (withinTolerance(difference(student, solution, tolerance.pixel, true), tolerance)) {
    out.cause = "inverted: the output is 1 minus the solution's (a comparison the wrong way round, or one "
                "1 - x too many)";
    return out;
  }
  // Visibility and AO are fractions: a value well outside [0, 1] where the solution stays inside is
  // a missing normalisation (a sum not divided by its count) or an unclamped formula.
  float lo = 0.0f, hi = 0.0f, solutionLo = 0.0f, solutionHi = 0.0f;
  finiteRange(student, solution, lo, hi);
  finiteRange(solution, solution, solutionLo, solutionHi);
  if (solutionLo >= 0.0f && solutionHi <= 1.0f && (lo < -0.01f || hi > 1.01f)) {
    out.cause = "range: values from " + short3(lo) + " to " + short3(hi) +
                " where the solution stays in [0, 1] (a sum not divided by its count, or a missing clamp?)";
    return out;
  }
  float value = 0.0f, solutionValue = 0.0f;
  if (constantOver(student, solution, value) && !constantOver(solution, solution, solutionValue)) {
    out.cause = "constant: every pixel is " + formatNumber(double(value)) + " where the solution varies";
    return out;
  }
  std::string what = percent(d.fraction) + " of the pixels differ by more than " + formatNumber(tolerance.pixel) +
                     " (allowed " + percent(tolerance.fraction) + "), RMSE " + short3(d.rmse);
  if (d.rmseAgreeing > tolerance.rmse)
    what += "; the other pixels are off by RMSE " + short3(d.rmseAgreeing) + " (allowed " + formatNumber(tolerance.rmse) +
            "): a small error everywhere";
  // The direction when at least 80% of the differing pixels agree on it.
  const double differing = double(d.darker + d.brighter);
  if (differing > 0 && std::max(d.darker, d.brighter) >= 0.8 * differing)
    what += d.darker > d.brighter ? "; mostly darker than the solution (more shadow or occlusion)"
                             : "; mostly brighter than the solution (less shadow or occlusion)";
  out.cause = "differs: " + what;
  return out;
}

} // namespace rtlab
