// Sample patterns and warps of the CPU reference (docs/measuring.md "Sampling").
//
// Per pixel and per 2D dimension pair, `spp` stratified points come from correlated
// multi-jittered sampling (Kensler, "Correlated Multi-Jittered Sampling", Pixar Technical Memo
// 13-01, 2013): the unit square is cut into m x n cells with m*n = spp (m the largest divisor of
// spp not above sqrt(spp)), one point per cell, and each 1D projection is stratified into spp
// intervals as well. When spp is a square this is a sqrt(spp) x sqrt(spp) jittered grid that is
// also a Latin hypercube; when spp is prime it is a Latin hypercube. Every (pixel, dimension pair)
// gets its own pattern from a hash of (seed, pixel, pair), and the sample order is shuffled per
// pair so that pairs are not correlated with each other. Nothing depends on the thread that runs
// a pixel, so images are identical for any thread count.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>

namespace rtlab::reference {

// A well-mixed 32-bit hash (the "lowbias32" finalizer of C. Wellons' hash-prospector).
std::uint32_t hash32(std::uint32_t x);
std::uint32_t hashCombine(std::uint32_t a, std::uint32_t b);

// The 2D points of one pixel for one dimension pair.
class PixelSampler {
public:
  // stratified = false gives independent uniform points (the plain Monte-Carlo estimator, used to
  // check the 1/sqrt(spp) rate and as a baseline in docs/measuring.md).
  PixelSampler(std::uint32_t seed, std::uint64_t pixel, int spp, bool stratified);
  // Point `s` in [0, spp) of dimension pair `pair`, in [0,1)^2.
  glm::vec2 get(int s, int pair) const;
  int spp() const { return m_spp; }

private:
  std::uint32_t m_key;
  int m_spp, m_m, m_n;
  bool m_stratified;
};

// The largest divisor of n that is not above sqrt(n) (the CMJ grid's column count).
int gridColumns(int n);

// Concentric map of the unit square onto the unit disk (Shirley and Chiu, "A Low Distortion Map
// Between Disk and Square", JGT 1997); it keeps the strata compact.
glm::vec2 squareToDisk(glm::vec2 u);
// Cosine-weighted direction about +z (Malley's method: a uniform disk point lifted to the
// hemisphere), pdf cos(theta)/pi.
glm::vec3 squareToCosineHemisphere(glm::vec2 u);
// Uniform direction in the cone of half-angle acos(cosMax) about +z, pdf 1/(2 pi (1 - cosMax)).
glm::vec3 squareToCone(glm::vec2 u, float cosMax);

// An orthonormal basis whose third axis is n (Duff et al., "Building an Orthonormal Basis,
// Revisited", JCGT 2017).
struct Frame {
  glm::vec3 t, b, n;
  explicit Frame(const glm::vec3& normal);
  glm::vec3 toWorld(const glm::vec3& v) const { return t * v.x + b * v.y + n * v.z; }
};

} // namespace rtlab::reference
