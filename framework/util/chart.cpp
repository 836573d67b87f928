#include "util/chart.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace rtlab {

std::vector<std::size_t> paretoFront(const std::vector<ChartPoint>& points) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (std::isfinite(points[i].x) && std::isfinite(points[i].y)) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (points[a].x != points[b].x) return points[a].x < points[b].x;
    return points[a].y < points[b].y;
  });
  std::vector<std::size_t> front;
  double best = INFINITY;
  for (std::size_t i : order) {
    if (points[i].y < best) {
      front.push_back(i);
      best = points[i].y;
    }
  }
  return front;
}

ChartAxis niceLinearAxis(double lo, double hi, int target) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) lo = 0, hi = 1;
  if (lo > hi) std::swap(lo, hi);
  if (hi - lo <= 1e-12 * std::max(std::abs(lo), std::abs(hi))) {
    const double pad = lo == 0 ? 1.0 : std::abs(lo) * 0.1;
    lo -= pad;
    hi += pad;
  }
  const double raw = (hi - lo) / std::max(1, target);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * magnitude;
    if (step >= raw) break;
  }
  ChartAxis axis;
  axis.min = std::floor(lo / step) * step;
  axis.max = std::ceil(hi / step) * step;
  const long long n = std::llround((axis.max - axis.min) / step);
  for (long long i = 0; i <= n; ++i) {
    double t = axis.min + double(i) * step;
    if (std::abs(t) < step * 1e-9) t = 0; // no "-0" or 1e-17 at the origin
    axis.ticks.push_back(t);
  }
  return axis;
}

ChartAxis niceLogAxis(double lo, double hi) {
  if (lo > hi) std::swap(lo, hi);
  ChartAxis axis;
  axis.log = true;
  const int first = int(std::floor(std::log10(lo)));
  int last = int(std::ceil(std::log10(hi)));
  if (last == first) ++last;
  axis.min = std::pow(10.0, first);
  axis.max = std::pow(10.0, last);
  const bool fine = last - first < 3;
  for (int e = first; e <= last; ++e) {
    const double p = std::pow(10.0, e);
    axis.ticks.push_back(p);
    if (fine && e < last) {
      axis.ticks.push_back(2 * p);
      axis.ticks.push_back(5 * p);
    }
  }
  return axis;
}

double axisFraction(const ChartAxis& axis, double v) {
  double f;
  if (axis.log) {
    const double a = std::log10(axis.min), b = std::log10(axis.max);
    f = (std::log10(std::max(v, axis.min * 1e-3)) - a) / (b - a);
  } else {
    f = (v - axis.min) / (axis.max - axis.min);
  }
  return std::clamp(f, 0.0, 1.0);
}

} // namespace rtlab
