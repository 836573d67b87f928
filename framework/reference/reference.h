// Ground truth on the CPU (Embree 3 + TBB) for the stage outputs, computed from the frame's own
// surface points over the same triangles the GPU draws (opaque instances; transparent surfaces
// neither receive nor cast in the data AOVs). DESIGN.md "Ground truth and metrics".
#pragma once
#include "image/image.h"
#include "reference/surfaces.h"
#include "scene/scene.h"

#include <string>

namespace rtlab {

struct ReferenceOptions {
  int spp = 64;            // samples per pixel (stratified)
  unsigned seed = 1;
  float aoRadius = 0.5f;   // ao.radius
  bool progress = false;   // progress bar on stderr
};

// aov: "visibility" (light 0), "ao" or "indirect". Returns an Image of the surfaces' size with 1
// (visibility, ao) or 3 (indirect) channels, background pixels 0, and the mask from `valid`.
// Deterministic for a given seed, whatever the number of threads. Error(Usage) for another AOV.
Image renderReference(const Scene& scene, const SurfaceData& surfaces, const std::string& aov,
                      const ReferenceOptions& options);

} // namespace rtlab
