#include "techniques/lpv/lpv_model.h"

#include <algorithm>
#include <cmath>

namespace rtlab::lpv {
namespace {

constexpr float kPi = 3.14159265358979f;
const float kY00 = 0.5f / std::sqrt(kPi);
const float kY1 = std::sqrt(3.0f / (4.0f * kPi));

} // namespace

GridFit fitGrid(const Bounds& bounds, int n) {
  GridFit g;
  g.n = std::max(n, 3);
  const glm::vec3 extent = bounds.valid() ? bounds.max - bounds.min : glm::vec3(1.0f);
  g.cellSize = std::max(std::max(extent.x, std::max(extent.y, extent.z)), 1e-4f) / float(g.n - 2);
  g.origin = (bounds.valid() ? bounds.center() : glm::vec3(0.0f)) - 0.5f * float(g.n) * g.cellSize;
  return g;
}

Sh4 shBasis(const glm::vec3& w) {
  return {kY00, kY1 * w.y, kY1 * w.z, kY1 * w.x};
}

Sh4 cosineLobe(const glm::vec3& n, int bands) {
  const float c1 = bands >= 2 ? std::sqrt(kPi / 3.0f) : 0.0f;
  return {std::sqrt(kPi) * 0.5f, c1 * n.y, c1 * n.z, c1 * n.x};
}

float shEval(const Sh4& c, const glm::vec3& w) {
  return glm::dot(c, shBasis(w));
}

float shFlux(const Sh4& c) {
  return 4.0f * kPi * kY00 * c.x;
}

float solidAngleNormalisation() {
  return 4.0f * kPi / (6.0f * (kFrontSolidAngle + 4.0f * kSideSolidAngle));
}

const std::array<glm::ivec3, 6>& axialDirections() {
  static const std::array<glm::ivec3, 6> kDirs = {glm::ivec3(1, 0, 0),  glm::ivec3(-1, 0, 0), glm::ivec3(0, 1, 0),
                                                  glm::ivec3(0, -1, 0), glm::ivec3(0, 0, 1),  glm::ivec3(0, 0, -1)};
  return kDirs;
}

std::array<PropagationFace, 5> propagationFaces(const glm::ivec3& d) {
  const float k = solidAngleNormalisation();
  const glm::vec3 df(d);
  std::array<PropagationFace, 5> faces;
  faces[0] = {df, df, kFrontSolidAngle * k};
  int i = 1;
  for (const glm::ivec3& e : axialDirections()) {
    if (e == d || e == -d) continue;
    const glm::vec3 ef(e);
    // The side face's centre seen from the source centre: one cell along d, half a cell along e.
    faces[std::size_t(i++)] = {glm::normalize(df + 0.5f * ef), ef, kSideSolidAngle * k};
  }
  return faces;
}

float Grid::totalFlux() const {
  double sum = 0.0;
  for (const Sh4& c : cells)
    sum += shFlux(c);
  return float(sum);
}

Grid propagate(const Grid& source, int bands, Blocking blocking, const void* user) {
  Grid out(source.n);
  for (int z = 0; z < source.n; ++z)
    for (int y = 0; y < source.n; ++y)
      for (int x = 0; x < source.n; ++x) {
        const glm::ivec3 dst(x, y, z);
        Sh4 sum(0.0f);
        for (const glm::ivec3& d : axialDirections()) {
          const glm::ivec3 src = dst - d;
          if (!source.inside(src)) continue;
          const Sh4& s = source.at(src.x, src.y, src.z);
          for (const PropagationFace& f : propagationFaces(d)) {
            float flux = f.solidAngle * shEval(s, f.direction);
            if (blocking) flux *= 1.0f - blocking(dst, d, f.direction, user);
            sum += (flux / kPi) * cosineLobe(f.normal, bands);
          }
        }
        out.at(x, y, z) = sum;
      }
  return out;
}

} // namespace rtlab::lpv
