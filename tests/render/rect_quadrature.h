// The arealight integral at one surface point (docs/contract.md "Area lights") as an area integral,
// L_e f(v, l) cos(theta_l) cos(theta') / r^2 dA over the rectangle, by the midpoint rule on
// nx x ny cells: the independent check of the reference's estimator (test_area_mc_reference.cpp)
// and of ltc (test_ltc.cpp). It shares nothing with either but the BRDF (shading/brdf_model.h).
#pragma once
#include "shading/brdf_model.h"
#include "techniques/area_mc/area_mc_model.h"

#include <cmath>

namespace rtlab::test {

enum class BrdfTerm {
  Full,    // evaluateBrdfCos: ((1 - F)(1 - metallic) baseColor / pi + D V F) n.l
  Diffuse, // its diffuse part only, (1 - F)(1 - metallic) baseColor / pi n.l
};

inline glm::dvec3 rectQuadrature(const area_mc::RectLight& light, const glm::dvec3& p, const glm::dvec3& n,
                                 const glm::dvec3& v, const brdf::Material& m, int nx, int ny,
                                 BrdfTerm term = BrdfTerm::Full) {
  glm::dvec3 sum(0.0);
  const double cell = light.area() / (double(nx) * double(ny));
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const glm::dvec3 q = light.center + ((i + 0.5) / nx - 0.5) * light.width * light.right +
                           ((j + 0.5) / ny - 0.5) * light.height * light.up;
      const glm::dvec3 d = q - p;
      const double r2 = glm::dot(d, d);
      const glm::dvec3 l = d / std::sqrt(r2);
      double cosLight = -glm::dot(l, light.normal);
      if (light.twoSided) cosLight = std::abs(cosLight);
      if (cosLight <= 0.0) continue;
      glm::dvec3 f;
      if (term == BrdfTerm::Full) {
        f = brdf::evaluateBrdfCos(n, v, l, m);
      } else {
        const double nDotL = glm::dot(n, l);
        if (nDotL <= 0.0) continue;
        const glm::dvec3 h = glm::normalize(l + v);
        const glm::dvec3 f0 = glm::mix(glm::dvec3(brdf::kDielectricF0), m.baseColor, m.metallic);
        const glm::dvec3 fresnel = f0 + (1.0 - f0) * brdf::schlickWeight(std::max(glm::dot(v, h), 0.0));
        f = (1.0 - fresnel) * (1.0 - m.metallic) * m.baseColor / brdf::kPi * nDotL;
      }
      sum += light.radiance * f * cosLight / r2 * cell;
    }
  }
  return sum;
}

} // namespace rtlab::test
