// The arealight integral on the CPU, in double precision (docs/contract.md "Area lights"): the
// radiance a rectangular light adds at a surface point, integral of L_e f(v, l) cos(theta_l) dw over
// the solid angle of the light's emitting face, unshadowed, clipped to the shading normal's
// hemisphere, with f the frame's BRDF (shading/brdf_model.h evaluateBrdfCos). The reference
// (area_mc_reference.cpp) estimates it per pixel with the same estimator the GPU technique runs
// (shaders/area_mc/area_mc.frag): one point on the rectangle (pdf 1/A over its area, turned into a
// solid-angle pdf r^2 / (A |cos theta'|)) and one GGX-sampled direction per sample, combined with
// the power heuristic (Veach & Guibas 1995). techniques/area_mc/README.md has the derivation.
#pragma once
#include "image/image.h"
#include "reference/sampling.h"
#include "reference/surfaces.h"
#include "scene/scene.h"
#include "shading/brdf_model.h"

#include <atomic>
#include <glm/glm.hpp>

#include <vector>

namespace rtlab::area_mc {

// A rectangular light as the integral sees it: centre, unit emitting normal, unit axes, size,
// radiance L_e = colour x intensity (nits).
struct RectLight {
  glm::dvec3 center{0.0}, normal{0.0, -1.0, 0.0}, right{1.0, 0.0, 0.0}, up{0.0, 0.0, 1.0};
  double width = 1.0, height = 1.0;
  glm::dvec3 radiance{1.0};
  bool twoSided = false;
  double area() const { return width * height; }
};
RectLight rectLightFrom(const Light& light);
// The scene's rectangular lights, in light order.
std::vector<RectLight> rectLights(const Scene& scene);

// What is integrated at one surface point: position, unit shading normal, unit direction to the
// viewer, the G-buffer's material.
struct ShadingPoint {
  glm::dvec3 position{0.0}, normal{0.0, 0.0, 1.0}, toViewer{0.0, 0.0, 1.0};
  brdf::Material material;
};

// The emitted radiance toward `p` from the light point `x` (L_e, or 0 where p lies behind a
// one-sided face), with |cos theta'| at the light in `cosLight`.
glm::dvec3 emittedToward(const RectLight& light, const glm::dvec3& x, const glm::dvec3& p, double& cosLight);

// Where the ray p + t l (l unit, t > 0) meets the rectangle: true with the distance t; false when
// it misses it.
bool intersect(const RectLight& light, const glm::dvec3& p, const glm::dvec3& l, double& t);

enum class Strategy { Mis, Light, Brdf };

// One sample of the estimator: uLight picks the point of the rectangle, uBrdf the GGX half vector.
// Mis: both, weighted with the power heuristic (exponent 2); Light or Brdf: that one alone (for
// tests and the README's firefly comparison). Returns radiance (the sample's estimate).
glm::dvec3 sampleRect(const ShadingPoint& x, const RectLight& light, glm::dvec2 uLight, glm::dvec2 uBrdf,
                      Strategy strategy = Strategy::Mis);

// The mean of `spp` samples, stratified per dimension pair by `sampler` (pairs firstPair and
// firstPair + 1).
glm::dvec3 estimateRect(const ShadingPoint& x, const RectLight& light, const reference::PixelSampler& sampler,
                        int firstPair, Strategy strategy = Strategy::Mis);

struct ReferenceJob {
  int spp = 256;
  unsigned seed = 1;
  bool progress = false;
  bool stratified = true;
  const std::atomic<bool>* cancel = nullptr; // Error(Interrupted) once set
  unsigned threads = 0;                      // 0: the hardware's
};

// The AOV `arealight` (3 channels, mask = surface pixels, 0 on background) from the frame's
// surface points: every rectangular light of `scene`, seen from scene.camera.position. Parallel
// over rows (TBB), deterministic for a seed whatever the thread count.
Image renderArealightReference(const Scene& scene, const SurfaceData& surfaces, const ReferenceJob& job);

} // namespace rtlab::area_mc
