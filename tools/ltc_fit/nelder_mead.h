// Nelder-Mead downhill simplex (Nelder & Mead 1965) with the standard coefficients (reflection 1,
// expansion 2, contraction 1/2, shrink 1/2), for the LTC fit's few parameters. Deterministic: the
// same start, steps and function give the same result.
#pragma once
#include <functional>
#include <vector>

namespace rtlab::ltcfit {

struct NelderMeadResult {
  std::vector<double> x;
  double value = 0.0;
  int evaluations = 0;
};

// Minimises f from x0, the initial simplex being x0 and x0 + step[k] e_k. Stops when the simplex's
// values agree within relTolerance (relative to the best value, plus 1e-300) or after
// maxEvaluations evaluations of f.
NelderMeadResult nelderMead(const std::function<double(const std::vector<double>&)>& f, const std::vector<double>& x0,
                            const std::vector<double>& step, double relTolerance, int maxEvaluations);

} // namespace rtlab::ltcfit
