#include "ltc_lobe.h"

#include "shading/brdf_model.h"

#include <algorithm>
#include <cmath>

namespace rtlab::ltcfit {

glm::dvec3 sampleCosine(double u1, double u2) {
  const double r = std::sqrt(u1), phi = 2.0 * brdf::kPi * u2;
  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u1))};
}

LtcLobe::LtcLobe(const glm::dmat3& m) : m_m(m) {
  const double det = glm::determinant(m);
  m_valid = std::isfinite(det) && std::abs(det) > 1e-300;
  if (!m_valid) return;
  m_mInv = glm::inverse(m);
  m_detInv = std::abs(glm::determinant(m_mInv));
  m_valid = std::isfinite(m_detInv);
}

double LtcLobe::evaluate(const glm::dvec3& w) const {
  if (!m_valid) return 0.0;
  const glm::dvec3 o = m_mInv * w;
  const double len = glm::length(o);
  if (!(len > 0.0)) return 0.0;
  const double cosine = std::max(o.z / len, 0.0) / brdf::kPi;
  return cosine * m_detInv / (len * len * len);
}

glm::dvec3 LtcLobe::sample(double u1, double u2) const { return glm::normalize(m_m * sampleCosine(u1, u2)); }

} // namespace rtlab::ltcfit
