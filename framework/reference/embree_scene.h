// The scene's opaque triangles in an Embree 3 BVH, in world space, exactly as the GPU draws them:
// every opaque instance's mesh transformed by its world matrix (transparent instances are left
// out, as the G-buffer and the shadow maps leave them out), both faces, alpha-masked materials
// cut out by an Embree filter function with the G-buffer's test (alpha < cutoff discards).
#pragma once
#include "scene/scene.h"

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace rtlab::reference {

// What the estimators need at a ray hit.
struct RayHit {
  float t = 0.0f;
  glm::vec3 position{0.0f};        // interpolated from the triangle's world vertices
  glm::vec3 geometricNormal{0.0f}; // unit, facing the ray's origin
  glm::vec3 shadingNormal{0.0f};   // unit, interpolated vertex normal, in geometricNormal's hemisphere
  glm::vec3 shadingPoint{0.0f};    // the shadow terminator rule's point (reference/terminator.h)
  glm::vec2 uv{0.0f};
  const Material* material = nullptr; // null: the default material
};

class EmbreeScene {
public:
  // Keeps pointers into `scene` (materials, textures): the scene must outlive this object.
  explicit EmbreeScene(const Scene& scene); // Error(Internal) if Embree fails
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Is anything hit along origin + t*dir, t in [tnear, tfar)? dir is unit.
  bool occluded(const glm::vec3& origin, const glm::vec3& dir, float tnear, float tfar) const;
  // The nearest hit in [tnear, tfar), if any.
  bool intersect(const glm::vec3& origin, const glm::vec3& dir, float tnear, float tfar, RayHit& hit) const;

  // Up to 8 occlusion rays traced as one packet (rtcOccluded8): faster than one by one for the
  // rays of one pixel, which share an origin. Returns a bit mask of the occluded rays.
  struct Packet {
    int count = 0;
    glm::vec3 origin[8], direction[8];
    float tnear[8], tfar[8];
    void add(const glm::vec3& o, const glm::vec3& d, float near, float far) {
      origin[count] = o, direction[count] = d, tnear[count] = near, tfar[count] = far;
      ++count;
    }
  };
  unsigned occluded(const Packet& packet) const;
  // The nearest hits of up to 8 rays (rtcIntersect8); returns a bit mask of the rays that hit.
  unsigned intersect(const Packet& packet, RayHit hits[8]) const;

  std::size_t triangleCount() const { return m_triangles; }

  struct Geometry; // per-instance data kept for hit shading and the alpha filter

private:
  void describeHit(unsigned geomID, unsigned primID, float u, float v, float t, const glm::vec3& dir,
                   RayHit& hit) const;
  std::string m_error; // the first error Embree reported (declared first: outlives the device)
  std::unique_ptr<RTCDeviceTy, void (*)(RTCDevice)> m_device{nullptr, rtcReleaseDevice};
  std::unique_ptr<RTCSceneTy, void (*)(RTCScene)> m_rtcScene{nullptr, rtcReleaseScene};
  std::vector<std::unique_ptr<Geometry>> m_geometries; // indexed by Embree geometry id
  std::size_t m_triangles = 0;
};

// Where secondary rays from a surface point p start. p is where a ray (the camera's, or the
// previous bounce's) first met a surface, so the segment back toward that ray's origin is free
// space: the start is p + eps * (n + back), n the unit geometric normal on the side p was seen
// from and `back` the unit direction back along that ray, with
// eps = 2^-13 * max(|p.x|, |p.y|, |p.z|, 2^-5), an offset that scales with the position's
// magnitude as floating-point error does (the idea of Waechter and Binder, "A Fast and Robust
// Method for Avoiding Self-Intersection", Ray Tracing Gems ch. 6, 2019, with a margin for G-buffer
// positions, which the rasterizer interpolates). The normal part clears p's own surface; the part
// along `back` moves the start off a second surface that meets p's at a concave edge when p lies
// on that edge (the offset along n alone would slide along that surface's plane).
struct RayStart {
  glm::vec3 origin;
  float tnear;
};
RayStart rayStart(const glm::vec3& p, const glm::vec3& n, const glm::vec3& back);

} // namespace rtlab::reference
