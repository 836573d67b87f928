#include "techniques/common/sdf/sdf_volume.h"

#include "scene/world_triangles.h"
#include "util/error.h"
#include "util/hash.h"

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <unordered_map>
#include <utility>

namespace rtlab::sdf {

Grid fitGrid(const Bounds& bounds, int resolution, int padding) {
  if (resolution < 2 * padding + 2) throw Error(ExitCode::Internal, "sdf grid: resolution below twice the padding");
  Bounds b = bounds;
  if (!b.valid()) b = Bounds{glm::vec3(-0.5f), glm::vec3(0.5f)};
  const glm::vec3 extent = glm::max(b.max - b.min, glm::vec3(1e-6f));
  const float longest = std::max(extent.x, std::max(extent.y, extent.z));
  Grid g;
  g.voxel = longest / float(resolution - 2 * padding);
  for (int a = 0; a < 3; ++a) {
    const int inner = std::max(1, int(std::ceil(extent[a] / g.voxel - 1e-4f)));
    g.dims[a] = std::min(resolution, inner + 2 * padding);
  }
  // Centred: the rounding's slack is split between both sides, so each keeps >= padding voxels.
  g.origin = b.center() - 0.5f * glm::vec3(g.dims) * g.voxel;
  g.padding = float(padding) * g.voxel;
  return g;
}

// Welded triangles of one part. Per triangle: the three corners (welded vertex ids, wound so that the face
// normal agrees with the mesh's vertex normals), the face normal and the pseudo-normals of its
// three edges (ab, bc, ca). Per vertex: the angle-weighted pseudo-normal.
struct TriangleDistance::Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> vertexNormals;
  std::vector<glm::uvec3> triangles;
  std::vector<glm::vec3> faceNormals;
  std::vector<std::array<glm::vec3, 3>> edgeNormals;
};

namespace {

struct PositionKey {
  std::uint32_t x, y, z;
  bool operator==(const PositionKey& o) const { return x == o.x && y == o.y && z == o.z; }
};
struct PositionKeyHash {
  std::size_t operator()(const PositionKey& k) const {
    return std::size_t(k.x) * 73856093u ^ std::size_t(k.y) * 19349663u ^ std::size_t(k.z) * 83492791u;
  }
};
PositionKey keyOf(glm::vec3 p) {
  PositionKey k{};
  p += glm::vec3(0.0f); // -0 -> +0
  std::memcpy(&k.x, &p.x, 4);
  std::memcpy(&k.y, &p.y, 4);
  std::memcpy(&k.z, &p.z, 4);
  return k;
}

float cornerAngle(const glm::vec3& at, const glm::vec3& u, const glm::vec3& v) {
  const glm::vec3 a = glm::normalize(u - at), b = glm::normalize(v - at);
  return std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f));
}

// Closest point of triangle abc to p (Ericson 2005, "Real-Time Collision Detection" 5.1.5) and the
// feature it lies on: 0..2 the corners a, b, c; 3 edge ab, 4 edge bc, 5 edge ca; 6 the face.
glm::vec3 closestOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                            int& feature) {
  const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
  const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0f && d2 <= 0.0f) return feature = 0, a;
  const glm::vec3 bp = p - b;
  const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0f && d4 <= d3) return feature = 1, b;
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return feature = 3, a + ab * (d1 / (d1 - d3));
  const glm::vec3 cp = p - c;
  const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0f && d5 <= d6) return feature = 2, c;
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return feature = 5, a + ac * (d2 / (d2 - d6));
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0.0f && d4 - d3 >= 0.0f && d5 - d6 >= 0.0f)
    return feature = 4, b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const float denom = 1.0f / (va + vb + vc);
  feature = 6;
  return a + ab * (vb * denom) + ac * (vc * denom);
}

struct Closest {
  const TriangleDistance::Mesh* mesh = nullptr;
  glm::vec3 p{0.0f};
  glm::vec3 point{0.0f};
  unsigned triangle = 0;
  int feature = -1;
};

bool closestCallback(RTCPointQueryFunctionArguments* args) {
  Closest& q = *static_cast<Closest*>(args->userPtr);
  const glm::uvec3 t = q.mesh->triangles[args->primID];
  int feature = 0;
  const glm::vec3 c = closestOnTriangle(q.p, q.mesh->positions[t.x], q.mesh->positions[t.y], q.mesh->positions[t.z], feature);
  const float d = glm::length(q.p - c);
  if (d >= args->query->radius) return false;
  args->query->radius = d;
  q.point = c;
  q.triangle = args->primID;
  q.feature = feature;
  return true;
}

} // namespace

// One closed or open surface: an opaque instance's triangles, welded, with their BVH. The union of
// the parts is min over the parts' signed distances (exact outside every part; inside, the depth
// in the part that holds the point deepest): one query over all triangles would let an open part
// (the ground) decide the sign inside a closed one resting on it.
struct TriangleDistance::Part {
  Mesh mesh;
  Bounds bounds;
  std::unique_ptr<RTCSceneTy, void (*)(RTCScene)> bvh{nullptr, rtcReleaseScene};
};

namespace {

void addPseudoNormals(TriangleDistance::Mesh& m) {
  // Vertex pseudo-normals: face normals weighted by the incident angle; edge pseudo-normals: the
  // sum of the faces sharing the edge (one face on a boundary: its own normal).
  m.vertexNormals.assign(m.positions.size(), glm::vec3(0.0f));
  std::map<std::pair<std::uint32_t, std::uint32_t>, glm::vec3> edges;
  auto edgeKey = [](std::uint32_t u, std::uint32_t v) { return std::make_pair(std::min(u, v), std::max(u, v)); };
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    const glm::uvec3 t = m.triangles[i];
    const glm::vec3 n = m.faceNormals[i];
    const glm::vec3 a = m.positions[t.x], b = m.positions[t.y], c = m.positions[t.z];
    m.vertexNormals[t.x] += cornerAngle(a, b, c) * n;
    m.vertexNormals[t.y] += cornerAngle(b, c, a) * n;
    m.vertexNormals[t.z] += cornerAngle(c, a, b) * n;
    edges[edgeKey(t.x, t.y)] += n;
    edges[edgeKey(t.y, t.z)] += n;
    edges[edgeKey(t.z, t.x)] += n;
  }
  m.edgeNormals.resize(m.triangles.size());
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    const glm::uvec3 t = m.triangles[i];
    m.edgeNormals[i] = {edges[edgeKey(t.x, t.y)], edges[edgeKey(t.y, t.z)], edges[edgeKey(t.z, t.x)]};
  }
}

// Distance from p to an axis-aligned box (0 inside).
float boxDistance(const Bounds& b, const glm::vec3& p) {
  return glm::length(glm::max(glm::max(b.min - p, p - b.max), glm::vec3(0.0f)));
}

} // namespace

TriangleDistance::TriangleDistance(const Scene& scene) {
  const WorldTriangles world = flattenWorldTriangles(scene);
  // flattenWorldTriangles lists instance after instance; a part ends where the next instance's
  // vertices begin (its triangles index only its own vertices).
  std::vector<std::size_t> firstVertex;
  std::size_t next = 0;
  for (const Instance& inst : scene.instances) {
    firstVertex.push_back(next);
    next += scene.meshes[std::size_t(inst.mesh)].vertices.size();
  }
  std::size_t tri = 0;
  for (std::size_t instance = 0; instance < scene.instances.size(); ++instance) {
    const std::size_t end = instance + 1 < firstVertex.size() ? firstVertex[instance + 1] : world.positions.size();
    auto part = std::make_unique<Part>();
    Mesh& m = part->mesh;
    std::unordered_map<PositionKey, std::uint32_t, PositionKeyHash> weld;
    auto welded = [&](std::uint32_t index) {
      const glm::vec3 p(world.positions[index]);
      auto [it, inserted] = weld.emplace(keyOf(p), std::uint32_t(m.positions.size()));
      if (inserted) m.positions.push_back(p);
      return it->second;
    };
    for (; tri < world.triangles.size() && world.triangles[tri].x < end; ++tri) {
      const glm::uvec4 t = world.triangles[tri];
      if (t.w & kTriangleTransparent) continue;
      glm::uvec3 w(welded(t.x), welded(t.y), welded(t.z));
      const glm::vec3 a = m.positions[w.x], b = m.positions[w.y], c = m.positions[w.z];
      glm::vec3 n = glm::cross(b - a, c - a);
      const float area2 = glm::length(n);
      if (!(area2 > 1e-12f) || w.x == w.y || w.y == w.z || w.z == w.x) continue; // degenerate: no face
      n /= area2;
      const glm::vec3 shading = glm::vec3(world.normals[t.x] + world.normals[t.y] + world.normals[t.z]);
      if (glm::dot(n, shading) < 0.0f) { // wound against its normals: the normals say which side is out
        std::swap(w.y, w.z);
        n = -n;
      }
      m.triangles.push_back(w);
      m.faceNormals.push_back(n);
    }
    if (m.triangles.empty()) continue;
    addPseudoNormals(m);
    for (const glm::uvec3& t : m.triangles)
      for (int k = 0; k < 3; ++k) part->bounds.extend(m.positions[t[k]]);
    m_bounds.extend(part->bounds);
    m_triangles += m.triangles.size();
    m_parts.push_back(std::move(part));
  }
  if (m_parts.empty()) return;

  m_device.reset(rtcNewDevice(nullptr));
  if (!m_device) throw Error(ExitCode::Internal, "sdf: Embree device creation failed");
  for (auto& part : m_parts) {
    const Mesh& m = part->mesh;
    part->bvh.reset(rtcNewScene(m_device.get()));
    RTCGeometry g = rtcNewGeometry(m_device.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), m.positions.size()));
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), m.triangles.size()));
    if (!v || !idx) throw Error(ExitCode::Internal, "sdf: Embree buffer allocation failed");
    std::memcpy(v, m.positions.data(), m.positions.size() * sizeof(glm::vec3));
    std::memcpy(idx, m.triangles.data(), m.triangles.size() * sizeof(glm::uvec3));
    rtcCommitGeometry(g);
    rtcAttachGeometry(part->bvh.get(), g);
    rtcReleaseGeometry(g);
    rtcCommitScene(part->bvh.get());
  }
}

TriangleDistance::~TriangleDistance() {
  m_parts.clear(); // the scenes before their device
}

float TriangleDistance::partDistance(const Part& part, const glm::vec3& p) const {
  const Mesh& m = part.mesh;
  RTCPointQuery query;
  query.x = p.x, query.y = p.y, query.z = p.z;
  query.radius = std::numeric_limits<float>::infinity();
  query.time = 0.0f;
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  Closest closest;
  closest.mesh = &m;
  closest.p = p;
  rtcPointQuery(part.bvh.get(), &query, &context, closestCallback, &closest);
  const float d = glm::length(p - closest.point);
  const glm::uvec3 t = m.triangles[closest.triangle];
  glm::vec3 pseudo;
  switch (closest.feature) {
  case 0: pseudo = m.vertexNormals[t.x]; break;
  case 1: pseudo = m.vertexNormals[t.y]; break;
  case 2: pseudo = m.vertexNormals[t.z]; break;
  case 3: case 4: case 5: pseudo = m.edgeNormals[closest.triangle][std::size_t(closest.feature - 3)]; break;
  default: pseudo = m.faceNormals[closest.triangle]; break;
  }
  return glm::dot(p - closest.point, pseudo) < 0.0f ? -d : d;
}

const Bounds& TriangleDistance::partBounds(std::size_t i) const {
  return m_parts.at(i)->bounds;
}

float TriangleDistance::partDistance(std::size_t i, const glm::vec3& p) const {
  return partDistance(*m_parts.at(i), p);
}

float TriangleDistance::signedDistance(const glm::vec3& p) const {
  float best = std::numeric_limits<float>::infinity();
  for (const auto& part : m_parts) {
    // A part cannot lower the minimum when it is farther than a positive minimum, or when p lies
    // outside its bounds (so it is positive there) and the minimum is already negative. A flat
    // part (the ground) has flat bounds, so below it p is outside them: it is queried only while
    // the minimum is positive.
    const float box = boxDistance(part->bounds, p);
    if (best > 0.0f ? box > best : box > 0.0f) continue;
    best = std::min(best, partDistance(*part, p));
  }
  return best;
}

namespace {

// Fills v.distance with `distance` at v.grid's voxel centres in parallel; times it in v.buildMs.
template <class Distance> void fillVolume(Volume& v, const Distance& distance) {
  v.distance.resize(v.grid.count());
  const Grid g = v.grid;
  const auto start = std::chrono::steady_clock::now();
  tbb::parallel_for(tbb::blocked_range<int>(0, g.dims.y * g.dims.z), [&](const tbb::blocked_range<int>& rows) {
    for (int row = rows.begin(); row != rows.end(); ++row) {
      const int j = row % g.dims.y, k = row / g.dims.y;
      float* out = v.distance.data() + std::size_t(row) * std::size_t(g.dims.x);
      for (int i = 0; i < g.dims.x; ++i) out[i] = distance(g.centre(i, j, k));
    }
  });
  v.buildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

Volume buildVolume(const Scene& scene, int resolution, int padding) {
  return buildVolume(TriangleDistance(scene), resolution, padding);
}

Volume buildVolume(const TriangleDistance& field, int resolution, int padding) {
  Volume v;
  v.triangles = field.triangleCount();
  if (v.triangles == 0) {
    v.grid = fitGrid(Bounds{}, 2 * padding + 2, padding);
    v.distance.assign(v.grid.count(), 1e6f);
    return v;
  }
  v.grid = fitGrid(field.bounds(), resolution, padding);
  fillVolume(v, [&](const glm::vec3& p) { return field.signedDistance(p); });
  return v;
}

std::vector<Volume> buildInstanceVolumes(const TriangleDistance& field, int resolution, int padding) {
  std::vector<Volume> volumes(field.partCount());
  for (std::size_t i = 0; i < volumes.size(); ++i) {
    Volume& v = volumes[i];
    v.grid = fitGrid(field.partBounds(i), resolution, padding);
    fillVolume(v, [&](const glm::vec3& p) { return field.partDistance(i, p); });
  }
  return volumes;
}

std::uint64_t geometryHash(const Scene& scene) {
  static_assert(sizeof(Vertex) == 12 * sizeof(float), "Vertex is hashed as raw floats");
  Fnv1a64 h;
  h.text("rtlab-sdf-geometry-1");
  for (const Instance& inst : scene.instances) {
    if (inst.transparent || inst.mesh < 0 || std::size_t(inst.mesh) >= scene.meshes.size()) continue;
    const Mesh& m = scene.meshes[std::size_t(inst.mesh)];
    h.u64(m.vertices.size()).bytes(m.vertices.data(), m.vertices.size() * sizeof(Vertex));
    h.u64(m.indices.size()).bytes(m.indices.data(), m.indices.size() * sizeof(std::uint32_t));
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) h.f32(inst.transform[c][r]);
  }
  return h.value();
}

} // namespace rtlab::sdf
