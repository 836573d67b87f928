// The frame's BRDF on the CPU, in double precision: exactly what shaders/common/brdf.glsl computes
// (Lambert diffuse weighted by (1 - F)(1 - metallic), GGX with the height-correlated Smith
// visibility, Schlick's Fresnel, the perceptual roughness squared and clamped to 0.045^2). The
// arealight reference integrates it, the LTC fitter (tools/ltc_fit) fits it, and tests check the
// GPU against it, so all three see one definition (docs/contract.md "Area lights").
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab::brdf {

inline constexpr double kPi = 3.14159265358979323846;
// alpha = max(roughness^2, kMinAlpha): brdf.glsl's clamp, so a mirror stays finite.
inline constexpr double kMinAlpha = 0.045 * 0.045;
// The dielectric reflectance at normal incidence (brdf.glsl: mix(vec3(0.04), baseColor, metallic)).
inline constexpr double kDielectricF0 = 0.04;

inline double alphaFromRoughness(double roughness) { return std::max(roughness * roughness, kMinAlpha); }

// Schlick's weight (1 - cos)^5: F = f0 + (1 - f0) * schlickWeight.
inline double schlickWeight(double cosTheta) { return std::pow(std::clamp(1.0 - cosTheta, 0.0, 1.0), 5.0); }

inline double distributionGgx(double nDotH, double alpha) {
  const double a2 = alpha * alpha;
  const double d = nDotH * nDotH * (a2 - 1.0) + 1.0;
  return a2 / std::max(kPi * d * d, 1e-12);
}

// V = G2 / (4 n.l n.v), height-correlated Smith for GGX (Heitz 2014).
inline double visibilitySmithGgx(double nDotL, double nDotV, double alpha) {
  const double a2 = alpha * alpha;
  const double gv = nDotL * std::sqrt(nDotV * nDotV * (1.0 - a2) + a2);
  const double gl = nDotV * std::sqrt(nDotL * nDotL * (1.0 - a2) + a2);
  return 0.5 / std::max(gv + gl, 1e-8);
}

// The specular lobe without Fresnel, times cos(theta_l): D V n.l, the quantity LTC fits. 0 below
// the horizon. n.v is clamped to 1e-4 as brdf.glsl does.
inline double specularCos(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, double alpha) {
  const double nDotL = glm::dot(n, l);
  if (nDotL <= 0.0) return 0.0;
  const double nDotV = std::max(glm::dot(n, v), 1e-4);
  const glm::dvec3 h = glm::normalize(l + v);
  const double nDotH = std::max(glm::dot(n, h), 0.0);
  return distributionGgx(nDotH, alpha) * visibilitySmithGgx(nDotL, nDotV, alpha) * nDotL;
}

struct Material {
  glm::dvec3 baseColor{0.5};
  double metallic = 0.0;
  double roughness = 0.5; // perceptual
};

// f(v, l) cos(theta_l) of brdf.glsl's evaluateBrdfCos: ((1 - F)(1 - metallic) baseColor / pi + D V F) n.l.
inline glm::dvec3 evaluateBrdfCos(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, const Material& m) {
  const double nDotL = glm::dot(n, l);
  if (nDotL <= 0.0) return glm::dvec3(0.0);
  const double nDotV = std::max(glm::dot(n, v), 1e-4);
  const glm::dvec3 h = glm::normalize(l + v);
  const double nDotH = std::max(glm::dot(n, h), 0.0);
  const double vDotH = std::max(glm::dot(v, h), 0.0);
  const double alpha = alphaFromRoughness(m.roughness);
  const glm::dvec3 f0 = glm::mix(glm::dvec3(kDielectricF0), m.baseColor, m.metallic);
  const glm::dvec3 f = f0 + (1.0 - f0) * schlickWeight(vDotH);
  const glm::dvec3 specular = distributionGgx(nDotH, alpha) * visibilitySmithGgx(nDotL, nDotV, alpha) * f;
  const glm::dvec3 diffuse = (1.0 - f) * (1.0 - m.metallic) * m.baseColor / kPi;
  return (diffuse + specular) * nDotL;
}

// A GGX half vector about +z (the distribution of normals, pdf D(h) h.z):
// phi = 2 pi u.x, cos(theta_h) = sqrt((1 - u.y) / ((alpha^2 - 1) u.y + 1)).
inline glm::dvec3 sampleGgxHalfVector(double alpha, double ux, double uy) {
  const double phi = 2.0 * kPi * ux;
  const double a2 = alpha * alpha;
  const double cosTheta = std::sqrt(std::max(0.0, (1.0 - uy) / ((a2 - 1.0) * uy + 1.0)));
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

// The density, over directions l, of reflecting v about a half vector drawn by
// sampleGgxHalfVector (normal n): D(h) n.h / (4 v.h). 0 when v.h <= 0.
inline double ggxReflectionPdf(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, double alpha) {
  const glm::dvec3 h = glm::normalize(l + v);
  const double vDotH = glm::dot(v, h);
  if (vDotH <= 0.0) return 0.0;
  const double nDotH = std::max(glm::dot(n, h), 0.0);
  return distributionGgx(nDotH, alpha) * nDotH / (4.0 * vDotH);
}

} // namespace rtlab::brdf
