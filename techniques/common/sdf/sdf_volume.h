// A signed distance volume of the scene's opaque triangles (techniques/sdf_shadow/README.md "The
// SDF"): built on the CPU with Embree closest-point queries (rtcPointQuery) over one BVH per
// instance of its world-space triangles, one query per voxel centre in parallel (TBB), each
// instance's distance signed with the angle-weighted pseudo-normal of its closest feature
// (Baerentzen & Aanaes 2005): exact for closed meshes; for open ones (a ground quad) the side the
// face normals point to is positive. The scene's value is the minimum over the instances.
// Transparent instances are left out, as the shadow maps leave them out. GL-free, so the distance
// at any point can be tested against closed forms.
#pragma once
#include "scene/scene.h"

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace rtlab::sdf {

// Cubic voxels over the opaque geometry's bounds padded by `padding` voxels on every side;
// `resolution` voxels along the longest padded axis, the other axes rounded up (so the padding is
// at least `padding` voxels everywhere). Voxel (i, j, k) has its centre at
// origin + (i + 0.5, j + 0.5, k + 0.5) * voxel.
struct Grid {
  glm::vec3 origin{0.0f}; // min corner of the box the voxels tile
  float voxel = 1.0f;     // edge length (scene units)
  glm::ivec3 dims{1};
  float padding = 0.0f;   // scene units between the box and the nearest geometry, at least
  glm::vec3 size() const { return glm::vec3(dims) * voxel; }
  glm::vec3 centre(int i, int j, int k) const { return origin + (glm::vec3(i, j, k) + 0.5f) * voxel; }
  std::size_t count() const { return std::size_t(dims.x) * std::size_t(dims.y) * std::size_t(dims.z); }
};
Grid fitGrid(const Bounds& bounds, int resolution, int padding);

// The signed distance to the union of the scene's opaque instances: min over the instances of each
// one's exact signed distance (one BVH each; queries are thread-safe).
class TriangleDistance {
public:
  // The opaque instances of `scene` in world space.
  explicit TriangleDistance(const Scene& scene);
  ~TriangleDistance();
  TriangleDistance(const TriangleDistance&) = delete;
  TriangleDistance& operator=(const TriangleDistance&) = delete;

  // Signed distance at p: negative behind the closest feature's pseudo-normal (inside a closed
  // mesh); +infinity when there are no triangles.
  float signedDistance(const glm::vec3& p) const;
  const Bounds& bounds() const { return m_bounds; } // of the opaque triangles
  std::size_t triangleCount() const { return m_triangles; }

  // The parts: one per opaque instance with triangles, in the scene's order. partDistance(i, p) is
  // part i's own signed distance (signedDistance is the minimum over the parts).
  std::size_t partCount() const { return m_parts.size(); }
  const Bounds& partBounds(std::size_t i) const;
  float partDistance(std::size_t i, const glm::vec3& p) const;

  struct Mesh; // welded triangles with their face, edge and vertex pseudo-normals
  struct Part; // one instance's Mesh and BVH

private:
  float partDistance(const Part& part, const glm::vec3& p) const;
  std::unique_ptr<RTCDeviceTy, void (*)(RTCDevice)> m_device{nullptr, rtcReleaseDevice};
  std::vector<std::unique_ptr<Part>> m_parts;
  Bounds m_bounds;
  std::size_t m_triangles = 0;
};

struct Volume {
  Grid grid;
  std::vector<float> distance; // signed, scene units; x fastest, then y, then z
  double buildMs = 0.0;        // wall time of the distance queries (not the BVH)
  std::size_t triangles = 0;
  float at(int i, int j, int k) const {
    return distance[(std::size_t(k) * std::size_t(grid.dims.y) + std::size_t(j)) * std::size_t(grid.dims.x) + std::size_t(i)];
  }
};

// The volume of `scene`'s opaque triangles. Without any, one voxel of +1e6 over a unit box.
Volume buildVolume(const Scene& scene, int resolution, int padding);
// The same from a field already built (the per-instance build's fallback builds no second one).
Volume buildVolume(const TriangleDistance& field, int resolution, int padding);

// One volume per part of `field` (per opaque instance), each over that part's own padded bounds
// with `resolution` voxels along its longest axis, holding that part's own signed distance: the
// scene's distance is the minimum over the volumes (outside a volume's box, the distance to the
// box plus its padding bounds its part from below). Empty when the field has no triangles.
std::vector<Volume> buildInstanceVolumes(const TriangleDistance& field, int resolution, int padding);

// Content hash of what the volume depends on: the opaque instances' meshes (positions, normals,
// indices) and transforms. Lights, camera and materials are left out, so moving a light keeps it.
std::uint64_t geometryHash(const Scene& scene);

} // namespace rtlab::sdf
