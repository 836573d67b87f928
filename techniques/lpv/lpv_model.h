// CPU model of light propagation volumes (techniques/lpv/README.md): the 2-band SH basis, the
// clamped-cosine lobe's coefficients, and one propagation step on a single-channel grid, the same
// arithmetic as shaders/lpv/ (sh.glsl, propagate.comp). The render tests check the GPU volume and
// the step's energy against it.
#pragma once
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace rtlab::lpv {

// The grid's placement (techniques/lpv/README.md "The grid"): n^3 cubic cells centred on the
// scene's bounds, the cell size the longest side over n - 2: along that side the bounds' faces lie
// on cell faces with one cell to spare beyond each (walls at the bounds are not at cell centres,
// where a VPL offset by half a cell would sit on a cell face and round either way).
struct GridFit {
  glm::vec3 origin{0}; // the corner of cell (0, 0, 0)
  float cellSize = 1.0f;
  int n = 1;
};
GridFit fitGrid(const Bounds& bounds, int n);

using Sh4 = glm::vec4; // (Y00, Y1-1, Y10, Y11) coefficients: constant, y, z, x

// Real SH basis, bands 0 and 1, at the unit direction w.
Sh4 shBasis(const glm::vec3& w);
// Coefficients of max(0, n.w): sqrt(pi)/2 for Y00, sqrt(pi/3) n for band 1 (bands = 1 keeps Y00 only).
Sh4 cosineLobe(const glm::vec3& n, int bands = 2);
// Value of the SH function at w.
float shEval(const Sh4& c, const glm::vec3& w);
// Integral over the sphere: the flux of an intensity distribution, 4 pi Y00 c00 = 2 sqrt(pi) c00.
float shFlux(const Sh4& c);

// The solid angles of a destination cell's faces seen from the source cell's centre
// (Kaplanyan & Dachsbacher 2010): the face opposite the shared one and each of the four side faces.
inline constexpr float kFrontSolidAngle = 0.4006696846f;
inline constexpr float kSideSolidAngle = 0.4234413544f;
// Scale that makes the 30 faces' solid angles sum to exactly 4 pi (they sum to 4 pi * 1.0000191),
// so that a step conserves the band-0 flux instead of gaining 2e-5 per iteration.
float solidAngleNormalisation();

// One face of a propagation: the direction from the source centre to the face centre, the face's
// outward normal (the reprojected lobe's axis) and its solid angle.
struct PropagationFace {
  glm::vec3 direction;
  glm::vec3 normal;
  float solidAngle;
};
// The five faces reached from a neighbour lying in direction -d (light travelling along +d).
std::array<PropagationFace, 5> propagationFaces(const glm::ivec3& d);
// The six axial directions +x -x +y -y +z -z.
const std::array<glm::ivec3, 6>& axialDirections();

// A cubic grid of SH intensity distributions, one channel.
struct Grid {
  int n = 0;
  std::vector<Sh4> cells;
  explicit Grid(int size) : n(size), cells(std::size_t(size) * size * size, Sh4(0.0f)) {}
  Sh4& at(int x, int y, int z) { return cells[(std::size_t(z) * n + y) * n + x]; }
  const Sh4& at(int x, int y, int z) const { return cells[(std::size_t(z) * n + y) * n + x]; }
  bool inside(const glm::ivec3& c) const {
    return glm::all(glm::greaterThanEqual(c, glm::ivec3(0))) && glm::all(glm::lessThan(c, glm::ivec3(n)));
  }
  float totalFlux() const;
};

// Blocking of the face between a source and a destination cell towards direction w, in [0, 1];
// null for no occlusion.
using Blocking = float (*)(const glm::ivec3& destination, const glm::ivec3& d, const glm::vec3& w, const void* user);

// One gather step: every destination cell sums, over its six neighbours and their five faces,
// Phi_f = dOmega_f * I_src(w_f) * (1 - V), reprojected as the lobe (Phi_f / pi) max(0, n_f.w).
// Light leaving the grid is lost. bands = 1 keeps band 0 of the reprojected lobes.
Grid propagate(const Grid& source, int bands = 2, Blocking blocking = nullptr, const void* user = nullptr);

} // namespace rtlab::lpv
