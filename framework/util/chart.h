// Pure helpers for the sweep report's chart: the Pareto front of (cost, error) points and "nice"
// axis ranges with ticks, linear (1, 2, 5 x 10^k steps) or logarithmic (decades).
#pragma once
#include <cstddef>
#include <vector>

namespace rtlab {

struct ChartPoint {
  double x = 0; // cost (ms)
  double y = 0; // error (rmse)
};

// Indices of the points no other point dominates (another point with x <= and y <= and one of
// them strictly smaller): the lowest error for each cost. Sorted by x ascending (so y falls).
// Points with a non-finite coordinate are never on the front; of equal points only the first is.
std::vector<std::size_t> paretoFront(const std::vector<ChartPoint>& points);

struct ChartAxis {
  double min = 0, max = 1;
  bool log = false;
  std::vector<double> ticks; // inside [min, max], ascending
};

// An axis covering [lo, hi] with about `target` ticks. lo == hi gets a range around the value.
ChartAxis niceLinearAxis(double lo, double hi, int target = 5);
// Decades covering [lo, hi] (both > 0); ticks at 1x10^k, plus 2x and 5x when the axis spans
// fewer than three decades.
ChartAxis niceLogAxis(double lo, double hi);

// Position of v on the axis as a fraction in [0, 1] (log axes in log10 space).
double axisFraction(const ChartAxis& axis, double v);

} // namespace rtlab
