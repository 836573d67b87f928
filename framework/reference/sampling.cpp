#include "reference/sampling.h"

#include <cmath>
#include <numbers>

namespace rtlab::reference {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Kensler 2013, listing 3: a hash-based permutation of [0, l) selected by p (cycle-walking over
// the next power of two).
std::uint32_t permute(std::uint32_t i, std::uint32_t l, std::uint32_t p) {
  if (l <= 1) return 0;
  std::uint32_t w = l - 1;
  w |= w >> 1;
  w |= w >> 2;
  w |= w >> 4;
  w |= w >> 8;
  w |= w >> 16;
  do {
    i ^= p;
    i *= 0xe170893du;
    i ^= p >> 16;
    i ^= (i & w) >> 4;
    i ^= p >> 8;
    i *= 0x0929eb3fu;
    i ^= p >> 23;
    i ^= (i & w) >> 1;
    i *= 1u | p >> 27;
    i *= 0x6935fa69u;
    i ^= (i & w) >> 11;
    i *= 0x74dcb303u;
    i ^= (i & w) >> 2;
    i *= 0x9e501cc3u;
    i ^= (i & w) >> 2;
    i *= 0xc860a3dfu;
    i &= w;
    i ^= i >> 5;
  } while (i >= l);
  return (i + p) % l;
}

// Kensler 2013, listing 3: a hashed float in [0, 1) selected by p.
float randFloat(std::uint32_t i, std::uint32_t p) {
  i ^= p;
  i ^= i >> 17;
  i ^= i >> 10;
  i *= 0xb36534e5u;
  i ^= i >> 12;
  i ^= i >> 21;
  i *= 0x93fc4795u;
  i ^= 0xdf6e307fu;
  i ^= i >> 17;
  i *= 1u | p >> 18;
  return float(i) * (1.0f / 4294967808.0f);
}

float toUnit(std::uint32_t x) { return float(x >> 8) * (1.0f / 16777216.0f); }

} // namespace

std::uint32_t hash32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

std::uint32_t hashCombine(std::uint32_t a, std::uint32_t b) { return hash32(a ^ (hash32(b) + 0x9e3779b9u + (a << 6) + (a >> 2))); }

int gridColumns(int n) {
  int m = int(std::sqrt(double(n)));
  while (m > 1 && n % m != 0) --m;
  return m < 1 ? 1 : m;
}

PixelSampler::PixelSampler(std::uint32_t seed, std::uint64_t pixel, int spp, bool stratified)
    : m_key(hashCombine(hashCombine(hash32(seed), std::uint32_t(pixel)), std::uint32_t(pixel >> 32))),
      m_spp(spp < 1 ? 1 : spp), m_m(gridColumns(m_spp)), m_n(m_spp / m_m), m_stratified(stratified) {}

glm::vec2 PixelSampler::get(int sample, int pair) const {
  const std::uint32_t p = hashCombine(m_key, std::uint32_t(pair));
  if (!m_stratified) {
    const std::uint32_t h = hashCombine(p, std::uint32_t(sample));
    return {toUnit(h), toUnit(hash32(h ^ 0x5bd1e995u))};
  }
  // Kensler 2013, listing 5 (cmj) with m * n = N: sample order shuffled per pattern.
  const auto N = std::uint32_t(m_spp), m = std::uint32_t(m_m), n = std::uint32_t(m_n);
  const std::uint32_t s = permute(std::uint32_t(sample), N, p * 0x51633e2du);
  const std::uint32_t sx = permute(s % m, m, p * 0xa511e9b3u);
  const std::uint32_t sy = permute(s / m, n, p * 0x63d83595u);
  const float jx = randFloat(s, p * 0xa399d265u);
  const float jy = randFloat(s, p * 0x711ad6a5u);
  glm::vec2 r((float(s % m) + (float(sy) + jx) / float(n)) / float(m),
              (float(s / m) + (float(sx) + jy) / float(m)) / float(n));
  // Rounding can reach 1.0 exactly; keep the half-open interval.
  return glm::min(r, glm::vec2(0x1.fffffep-1f));
}

glm::vec2 squareToDisk(glm::vec2 u) {
  const glm::vec2 o = 2.0f * u - 1.0f;
  if (o.x == 0.0f && o.y == 0.0f) return glm::vec2(0.0f);
  float r, theta;
  if (std::abs(o.x) > std::abs(o.y)) {
    r = o.x;
    theta = (kPi / 4.0f) * (o.y / o.x);
  } else {
    r = o.y;
    theta = kPi / 2.0f - (kPi / 4.0f) * (o.x / o.y);
  }
  return r * glm::vec2(std::cos(theta), std::sin(theta));
}

glm::vec3 squareToCosineHemisphere(glm::vec2 u) {
  const glm::vec2 d = squareToDisk(u);
  const float z = std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
  return {d.x, d.y, z};
}

glm::vec3 squareToCone(glm::vec2 u, float cosMax) {
  const float cosTheta = 1.0f - u.x * (1.0f - cosMax);
  const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
  const float phi = 2.0f * kPi * u.y;
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

Frame::Frame(const glm::vec3& normal) : n(normal) {
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float b2 = n.x * n.y * a;
  t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * b2, -sign * n.x);
  b = glm::vec3(b2, sign + n.y * n.y * a, -n.y);
}

} // namespace rtlab::reference
