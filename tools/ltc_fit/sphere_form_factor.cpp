#include "sphere_form_factor.h"

#include "shading/brdf_model.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace rtlab::ltcfit {
namespace {

using brdf::kPi;

// Integral over phi in [0, 2 pi) of max(a + b cos(phi), 0), b >= 0.
double clampedCosineRing(double a, double b) {
  if (a >= b) return 2.0 * kPi * a;
  if (a <= -b) return 0.0;
  const double phi0 = std::acos(-a / b); // a + b cos(phi) > 0 for |phi| < phi0
  return 2.0 * (a * phi0 + b * std::sin(phi0));
}

// 16-point Gauss-Legendre nodes and weights on [-1, 1] (positive half; symmetric).
constexpr std::array<double, 8> kNodes = {0.0950125098376374, 0.2816035507792589, 0.4580167776572274,
                                          0.6178762444026438, 0.7554044083550030, 0.8656312023878318,
                                          0.9445750230732326, 0.9894009349916499};
constexpr std::array<double, 8> kWeights = {0.1894506104550685, 0.1826034150449236, 0.1691565193950025,
                                            0.1495959888165767, 0.1246289712555339, 0.0951585116824928,
                                            0.0622535239386479, 0.0271524594117541};

template <class F> double gaussLegendre(const F& f, double lo, double hi) {
  const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  double sum = 0.0;
  for (std::size_t k = 0; k < kNodes.size(); ++k)
    sum += kWeights[k] * (f(mid - half * kNodes[k]) + f(mid + half * kNodes[k]));
  return sum * half;
}

} // namespace

double clippedCapFormFactor(double z, double length) {
  z = std::clamp(z, -1.0, 1.0);
  length = std::clamp(length, 0.0, 1.0);
  const double sigma = std::asin(std::sqrt(length)); // the cap's angular radius
  const double omega = std::acos(z);                 // its centre's angle from the normal
  // In the cap's own polar coordinates (t from the centre, phi around it):
  // n.w = cos(t) cos(omega) + sin(t) sin(omega) cos(phi).
  auto ring = [&](double t) {
    return clampedCosineRing(std::cos(t) * z, std::sin(t) * std::sin(omega)) * std::sin(t);
  };
  // The integrand is smooth but for kinks where a ring starts or stops crossing the horizon
  // (t = |pi/2 - omega|): integrate piecewise between them, each piece split further so that the
  // 16-point rule is exact to ~1e-12.
  std::vector<double> cuts = {0.0, sigma};
  const double kink = std::abs(0.5 * kPi - omega);
  if (kink > 0.0 && kink < sigma) cuts.push_back(kink);
  std::sort(cuts.begin(), cuts.end());
  double sum = 0.0;
  constexpr int kPieces = 8;
  for (std::size_t c = 0; c + 1 < cuts.size(); ++c)
    for (int p = 0; p < kPieces; ++p) {
      const double lo = cuts[c] + (cuts[c + 1] - cuts[c]) * p / kPieces;
      const double hi = cuts[c] + (cuts[c + 1] - cuts[c]) * (p + 1) / kPieces;
      sum += gaussLegendre(ring, lo, hi);
    }
  return sum / kPi;
}

double sphereTableValue(double z, double length) {
  if (length <= 0.0) return std::max(z, 0.0);
  return clippedCapFormFactor(z, length) / length;
}

} // namespace rtlab::ltcfit
