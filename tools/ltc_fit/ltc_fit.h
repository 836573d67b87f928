// The LTC fit of the frame's specular lobe D V cos (shading/brdf_model.h, Fresnel excluded), after
// Heitz, Dupuy, Hill & Neubelt 2016 and their published fitting procedure: per (view angle,
// roughness) cell, the lobe's magnitude, Fresnel part and average direction by importance
// sampling; then, in the frame whose z axis is the average direction, Nelder-Mead over the matrix
// M = [[m00, 0, m02], [0, m11, 0], [0, 0, 1]] minimising the cubed difference between the
// normalised lobe and the LTC, estimated with multiple importance sampling (as many GGX samples as
// LTC samples, balance heuristic); warm-started from the neighbouring cell (roughness from 1 down,
// one chain per view angle). assets/ltc/README.md describes the table and the error.
#pragma once
#include "techniques/common/arealight/ltc_table.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <functional>

namespace rtlab::ltcfit {

// The fitted matrix in the lobe's frame (z = the average direction, x in the plane of v and n).
struct LtcParams {
  double m00 = 1.0, m11 = 1.0, m02 = 0.0;
};

// What the fit of one cell needs to know about the lobe.
struct LobeMoments {
  double magnitude = 0.0;     // integral of D V cos
  double fresnel = 0.0;       // integral of D V cos (1 - v.h)^5
  glm::dvec3 averageDir{0.0, 0.0, 1.0}; // the lobe's mean direction, projected to the xz-plane
};

struct CellFit {
  LtcParams params;
  std::array<double, 4> mInv{}; // (a, b, c, d), normalised: see LtcTable
  LobeMoments moments;
  double error = 0.0;           // L1 difference of the normalised lobes (assets/ltc/README.md)
  int evaluations = 0;          // of the objective, over every Nelder-Mead run
};

struct FitOptions {
  int size = 64;
  int samples = 1024;  // per cell and per strategy of the MIS objective; the moments use 16x more
  std::uint64_t seed = 1;
  int threads = 1;
};

// The view vector of cos(theta_v): (sin, 0, cos), the frame of the table.
glm::dvec3 viewVector(double cosTheta);
// The lobe's frame: rotation whose columns are x, y, z = averageDir (in view-frame coordinates).
glm::dmat3 lobeFrame(const glm::dvec3& averageDir);
// M in the view frame for parameters in the lobe's frame.
glm::dmat3 viewMatrix(const LtcParams& p, const glm::dvec3& averageDir);
// (a, b, c, d) of M^-1 normalised so that its (1,1) element is 1, and back to M^-1.
std::array<double, 4> packInverse(const glm::dmat3& m);
glm::dmat3 unpackInverse(const std::array<double, 4>& abcd);
// The parameters (lobe frame) of a stored M^-1; used to warm-start from a committed table.
LtcParams paramsFromInverse(const std::array<double, 4>& abcd, const glm::dvec3& averageDir);

// The cell's own random stream: a hash of (seed, i, j, stream), the same whatever thread runs it.
std::uint64_t cellSeed(std::uint64_t seed, int i, int j, int stream);

LobeMoments lobeMoments(double alpha, double cosTheta, int samples, std::uint64_t seed);
// The moments of cell (i, j) exactly as fitCell computes them (its sample count and stream).
LobeMoments cellMoments(int i, int j, int n, int samples, std::uint64_t seed);
// Fits cell (i, j) of an n x n table (LtcTable's grid) from `start` (the neighbour's parameters),
// with the table's seed and per-cell sample count: exactly what fitTable computes for that cell.
CellFit fitCell(int i, int j, int n, const LtcParams& start, int samples, std::uint64_t seed);
// L1 difference between the normalised lobe (D V cos / magnitude) and the LTC of M (view frame),
// estimated by MIS with `samples` samples of each strategy.
double lobeL1Error(double alpha, double cosTheta, double magnitude, const glm::dmat3& m, int samples, std::uint64_t seed);
// L1 difference between two LTC distributions (0 when equal, 2 when disjoint), estimated by MIS
// with `samples` samples of each: how the tests compare lobes rather than parameters, which trade off.
double ltcL1Difference(const glm::dmat3& a, const glm::dmat3& b, int samples, std::uint64_t seed);
// (1/pi) integral of cos (1 - v.h)^5 over the hemisphere: a deterministic quadrature.
double diffuseFresnel(double cosTheta);

// The whole table; `progress` (may be empty) is called from the worker threads with the number of
// cells just finished. The result is the same for any thread count.
LtcTable fitTable(const FitOptions& options, const std::function<void(int)>& progress = {});

} // namespace rtlab::ltcfit
