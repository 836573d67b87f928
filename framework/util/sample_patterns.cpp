#include "util/sample_patterns.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rtlab {
namespace {

// xorshift32: small, deterministic across platforms.
struct Rng {
  std::uint32_t state;
  explicit Rng(std::uint32_t seed) : state(seed ? seed : 0x9E3779B9u) {}
  std::uint32_t next() {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return state;
  }
  float uniform() { return float(next() >> 8) * (1.0f / 16777216.0f); }
};

} // namespace

std::vector<glm::vec2> gridPattern(int n) {
  const int k = std::max(1, int(std::floor(std::sqrt(double(std::max(n, 1))))));
  std::vector<glm::vec2> points;
  for (int y = 0; y < k; ++y)
    for (int x = 0; x < k; ++x)
      points.emplace_back(k == 1 ? 0.0f : -1.0f + (2.0f * x + 1.0f) / k, k == 1 ? 0.0f : -1.0f + (2.0f * y + 1.0f) / k);
  return points;
}

std::vector<glm::vec2> poissonDiskPattern(int n, std::uint32_t seed) {
  Rng rng(seed * 2654435761u + std::uint32_t(n));
  std::vector<glm::vec2> points;
  if (n <= 0) return points;
  points.emplace_back(0.0f, 0.0f); // the first tap is the center: a 1-tap kernel is the hard test
  const int candidatesPerPoint = 32;
  while (int(points.size()) < n) {
    glm::vec2 best(0.0f);
    float bestDistance = -1.0f;
    for (int c = 0; c < candidatesPerPoint; ++c) {
      // Uniform in the disk: sqrt for the radius.
      const float r = std::sqrt(rng.uniform());
      const float a = 6.28318530718f * rng.uniform();
      const glm::vec2 p(r * std::cos(a), r * std::sin(a));
      float nearest = std::numeric_limits<float>::max();
      for (const auto& q : points) nearest = std::min(nearest, glm::dot(p - q, p - q));
      if (nearest > bestDistance) {
        bestDistance = nearest;
        best = p;
      }
    }
    points.push_back(best);
  }
  return points;
}

std::vector<float> blueNoise(int size, std::uint32_t seed) {
  const int n = size * size;
  const float sigma = 1.5f;
  const int radius = 4; // the Gaussian is negligible beyond ~2.7 sigma
  std::vector<float> kernel((2 * radius + 1) * (2 * radius + 1));
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx)
      kernel[(dy + radius) * (2 * radius + 1) + dx + radius] = std::exp(-(dx * dx + dy * dy) / (2.0f * sigma * sigma));
  std::vector<float> energy(n, 0.0f);
  std::vector<std::uint8_t> on(n, 0);
  auto splat = [&](int index, float sign) {
    const int x0 = index % size, y0 = index / size;
    for (int dy = -radius; dy <= radius; ++dy)
      for (int dx = -radius; dx <= radius; ++dx) {
        const int x = (x0 + dx + size) % size, y = (y0 + dy + size) % size;
        energy[y * size + x] += sign * kernel[(dy + radius) * (2 * radius + 1) + dx + radius];
      }
  };
  auto extreme = [&](bool wantOn, bool tightest) {
    int best = -1;
    float value = tightest ? -std::numeric_limits<float>::max() : std::numeric_limits<float>::max();
    for (int i = 0; i < n; ++i) {
      if (bool(on[i]) != wantOn) continue;
      if ((tightest && energy[i] > value) || (!tightest && energy[i] < value)) {
        value = energy[i];
        best = i;
      }
    }
    return best;
  };
  // Initial binary pattern: 10% random points, relaxed until the tightest cluster is the largest void.
  Rng rng(seed);
  const int initial = std::max(1, n / 10);
  for (int placed = 0; placed < initial;) {
    const int i = int(rng.next() % std::uint32_t(n));
    if (on[i]) continue;
    on[i] = 1;
    splat(i, 1.0f);
    ++placed;
  }
  for (int iteration = 0; iteration < n; ++iteration) {
    const int cluster = extreme(true, true);
    on[cluster] = 0;
    splat(cluster, -1.0f);
    const int voidIndex = extreme(false, false);
    on[voidIndex] = 1;
    splat(voidIndex, 1.0f);
    if (voidIndex == cluster) break;
  }
  std::vector<int> rank(n, 0);
  // Phase 1: remove points from the tightest clusters, ranking downward.
  std::vector<std::uint8_t> prototype = on;
  std::vector<float> prototypeEnergy = energy;
  for (int r = initial - 1; r >= 0; --r) {
    const int cluster = extreme(true, true);
    on[cluster] = 0;
    splat(cluster, -1.0f);
    rank[cluster] = r;
  }
  // Phase 2 and 3: from the prototype, fill the largest voids, ranking upward.
  on = prototype;
  energy = prototypeEnergy;
  for (int r = initial; r < n; ++r) {
    const int voidIndex = extreme(false, false);
    on[voidIndex] = 1;
    splat(voidIndex, 1.0f);
    rank[voidIndex] = r;
  }
  std::vector<float> out(n);
  for (int i = 0; i < n; ++i) out[i] = (float(rank[i]) + 0.5f) / float(n);
  return out;
}

} // namespace rtlab
