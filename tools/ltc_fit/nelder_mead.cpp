#include "nelder_mead.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace rtlab::ltcfit {

NelderMeadResult nelderMead(const std::function<double(const std::vector<double>&)>& f, const std::vector<double>& x0,
                            const std::vector<double>& step, double relTolerance, int maxEvaluations) {
  const std::size_t n = x0.size();
  std::vector<std::vector<double>> simplex(n + 1, x0);
  std::vector<double> values(n + 1);
  int evaluations = 0;
  auto eval = [&](const std::vector<double>& x) {
    ++evaluations;
    const double v = f(x);
    return std::isfinite(v) ? v : HUGE_VAL;
  };
  for (std::size_t k = 0; k < n; ++k) simplex[k + 1][k] += step[k];
  for (std::size_t k = 0; k <= n; ++k) values[k] = eval(simplex[k]);

  std::vector<std::size_t> order(n + 1);
  auto affine = [&](const std::vector<double>& a, const std::vector<double>& b, double t) {
    std::vector<double> r(n);
    for (std::size_t k = 0; k < n; ++k) r[k] = a[k] + t * (b[k] - a[k]);
    return r;
  };
  while (true) {
    std::iota(order.begin(), order.end(), std::size_t(0));
    // Stable: ties keep index order, so the run is deterministic.
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
    const std::size_t best = order.front(), worst = order.back(), second = order[n - 1];
    const double spread = std::abs(values[worst] - values[best]);
    if (spread <= relTolerance * std::abs(values[best]) + 1e-300 || evaluations >= maxEvaluations) break;

    std::vector<double> centroid(n, 0.0);
    for (std::size_t k = 0; k <= n; ++k)
      if (k != worst)
        for (std::size_t d = 0; d < n; ++d) centroid[d] += simplex[k][d] / double(n);

    const std::vector<double> reflected = affine(centroid, simplex[worst], -1.0);
    const double fr = eval(reflected);
    if (fr < values[best]) {
      const std::vector<double> expanded = affine(centroid, simplex[worst], -2.0);
      const double fe = eval(expanded);
      if (fe < fr) simplex[worst] = expanded, values[worst] = fe;
      else simplex[worst] = reflected, values[worst] = fr;
      continue;
    }
    if (fr < values[second]) {
      simplex[worst] = reflected, values[worst] = fr;
      continue;
    }
    // Contraction: outside when the reflection beat the worst point, inside otherwise.
    const bool outside = fr < values[worst];
    const std::vector<double> contracted = affine(centroid, outside ? reflected : simplex[worst], 0.5);
    const double fc = eval(contracted);
    if (fc < (outside ? fr : values[worst])) {
      simplex[worst] = contracted, values[worst] = fc;
      continue;
    }
    for (std::size_t k = 0; k <= n; ++k) {
      if (k == best) continue;
      simplex[k] = affine(simplex[best], simplex[k], 0.5);
      values[k] = eval(simplex[k]);
    }
  }
  const std::size_t best = std::size_t(std::min_element(values.begin(), values.end()) - values.begin());
  return {simplex[best], values[best], evaluations};
}

} // namespace rtlab::ltcfit
