// A linearly transformed cosine (Heitz et al. 2016): the clamped cosine D_o(w) = max(w.z, 0)/pi
// transformed by a 3x3 matrix M, D(w) = D_o(M^-1 w / |M^-1 w|) |det M^-1| / |M^-1 w|^3. It is a
// distribution over the sphere (it integrates to 1) and is sampled exactly by transforming
// cosine-distributed directions by M.
#pragma once
#include <glm/glm.hpp>

namespace rtlab::ltcfit {

class LtcLobe {
public:
  explicit LtcLobe(const glm::dmat3& m);
  double evaluate(const glm::dvec3& w) const;       // the density at unit direction w
  glm::dvec3 sample(double u1, double u2) const;    // a unit direction drawn with density evaluate()
  const glm::dmat3& m() const { return m_m; }
  const glm::dmat3& mInv() const { return m_mInv; }
  bool valid() const { return m_valid; } // false when M is singular or not finite

private:
  glm::dmat3 m_m, m_mInv;
  double m_detInv = 0.0;
  bool m_valid = false;
};

// A cosine-distributed direction about +z (density z/pi) from two uniform numbers.
glm::dvec3 sampleCosine(double u1, double u2);

} // namespace rtlab::ltcfit
