// Ground truth on the CPU (Embree 3 + TBB) for the stage outputs, computed from the frame's own
// surface points over the same triangles the GPU draws (opaque instances; transparent surfaces
// neither receive nor cast in the data AOVs). docs/measuring.md "Where the rays start".
#pragma once
#include "image/image.h"
#include "reference/surfaces.h"
#include "scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace rtlab {

struct ReferenceOptions {
  int spp = 64;            // samples per pixel (stratified)
  unsigned seed = 1;
  float aoRadius = 0.5f;   // ao.radius
  bool progress = false;   // progress bar on stderr
  bool stratified = true;  // false: independent uniform samples (plain Monte Carlo; for tests)
};

// Cost of one reference image: rays cast (shadow, AO and bounce rays) and wall time of the ray
// casting (BVH build included).
struct ReferenceStats {
  std::uint64_t rays = 0;
  double seconds = 0.0;
  std::size_t triangles = 0;
};

// aov: "visibility" (light 0), "ao" or "indirect". Returns an Image of the surfaces' size with 1
// (visibility, ao) or 3 (indirect) channels, background pixels 0, and the mask from `valid`.
// Deterministic for a given seed, whatever the number of threads. Error(Usage) for another AOV.
Image renderReference(const Scene& scene, const SurfaceData& surfaces, const std::string& aov,
                      const ReferenceOptions& options);
Image renderReference(const Scene& scene, const SurfaceData& surfaces, const std::string& aov,
                      const ReferenceOptions& options, ReferenceStats& stats);

// The AOVs the reference computes, and its sample-count range (docs/contract.md `rtlab reference`).
bool isReferenceAov(const std::string& aov);
constexpr int kReferenceMinSpp = 1, kReferenceMaxSpp = 65536;

} // namespace rtlab
