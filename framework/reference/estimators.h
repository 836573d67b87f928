// The per-pixel Monte-Carlo estimators of the reference (docs/measuring.md): visibility of light 0,
// ambient occlusion within a radius, one-bounce diffuse irradiance. Each takes one camera-visible
// surface point and the pixel's sampler and counts the rays it casts.
#pragma once
#include "reference/embree_scene.h"
#include "reference/sampling.h"
#include "scene/scene.h"

#include <cstdint>
#include <vector>

namespace rtlab::reference {

struct SurfacePoint {
  glm::vec3 position;
  glm::vec3 geometricNormal; // unit, on the side the point is seen from
  glm::vec3 shadingNormal;   // unit, in the geometric normal's hemisphere
  glm::vec3 toViewer;        // unit, toward the camera that saw the point (see rayStart)
  // The shadow terminator rule (docs/measuring.md, "The shading point"): rays start from
  // shadingPoint (the point on the vertex normals' smooth surface) and directions below the
  // tangent plane of smoothNormal (unit, the interpolated vertex normal) count as blocked.
  glm::vec3 shadingPoint;
  glm::vec3 smoothNormal;
};

struct EstimatorContext {
  const Scene& scene; // materials and textures (those `tracer` was built from)
  const EmbreeScene& tracer;
  float aoRadius = 0.5f;
  const std::vector<Light>& lights; // usually scene.lights; the progressive reference edits them apart
};

// Fraction of light 0 visible from the point: the mean of binary shadow rays from the shading
// point toward uniform points of the light's shape; one ray for a light without extent. Points of
// the light below the smooth normal's tangent plane count as hidden (the surface hides them).
float estimateVisibility(const EstimatorContext& ctx, const SurfacePoint& x, const PixelSampler& sampler,
                         std::uint64_t& rays);

// (1/pi) * integral of V_R(w) cos(theta) dw over the hemisphere of the shading normal, with
// V_R = 1 when no surface lies within aoRadius: the mean of V_R over cosine-weighted directions.
// Rays start from the shading point; directions below the smooth normal's tangent plane count as
// occluded.
float estimateAo(const EstimatorContext& ctx, const SurfacePoint& x, const PixelSampler& sampler, std::uint64_t& rays);

// E(x) = integral of L(w) cos(theta) dw with L the radiance that the first surface hit along w
// reflects diffusely: (albedo / pi) * its direct irradiance from every light (the GPU's light
// model, each light shadowed by one ray to a point of its shape). Cosine-weighted sampling about
// the shading normal makes each sample albedo * E_direct(hit).
glm::vec3 estimateIndirect(const EstimatorContext& ctx, const SurfacePoint& x, const PixelSampler& sampler,
                           std::uint64_t& rays);

} // namespace rtlab::reference
