// Deterministic sample patterns for filtering kernels (PCF, PCSS, SSAO ...): points in the unit
// disk, and a tileable blue-noise texture for per-pixel rotation.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace rtlab {

// k x k points on a regular grid covering [-1,1]^2 (cell centers), k = max(1, floor(sqrt(n))).
std::vector<glm::vec2> gridPattern(int n);

// n points in the unit disk with Poisson-disk-like spacing, by Mitchell's best-candidate
// algorithm (Mitchell 1991): each new point is the candidate farthest from the points so far.
// Deterministic for (n, seed). The first point is the center, so a 1-tap kernel is the plain test.
std::vector<glm::vec2> poissonDiskPattern(int n, std::uint32_t seed = 1);

// size x size blue-noise ranks by the void-and-cluster method (Ulichney 1993), Gaussian energy
// with sigma 1.5 on a torus; values are the ranks scaled to [0, 1). Tileable, deterministic.
std::vector<float> blueNoise(int size, std::uint32_t seed = 1);

} // namespace rtlab
