// The "umbra speckle share" of a shadow technique (issue 12, techniques/vssm/README.md and
// techniques/msm/README.md "Speckles"): the fraction of the reference's deep umbra where the
// technique lets light through. Deep umbra: surface pixels whose reference visibility is exactly 0
// and whose whole (2 erode + 1)^2 neighbourhood is surface with reference 0, so penumbrae,
// silhouettes and the reference's own noise at umbra edges never count. A speckle: a deep-umbra
// pixel whose visibility exceeds `threshold`.
#pragma once
#include "image/image.h"

#include <cstddef>

namespace rtlab {

struct UmbraSpeckles {
  std::size_t umbraPixels = 0; // deep-umbra pixels of the reference
  std::size_t speckles = 0;    // of those, pixels with visibility > threshold
  double share() const { return umbraPixels ? double(speckles) / double(umbraPixels) : 0.0; }
};

// Both images one channel of the same size (Error(Input) otherwise); a mask, where present, limits
// the umbra to surface pixels of both; non-finite visibility counts as a speckle.
UmbraSpeckles measureUmbraSpeckles(const Image& reference, const Image& visibility, int erode = 3,
                                   float threshold = 0.05f);

} // namespace rtlab
