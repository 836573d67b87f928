// The umbra leak of a shadow technique: its mean visibility over the surface pixels where the
// reference is exactly 0 (fully shadowed), i.e. the light it lets into umbrae. The measure of
// docs/performance.md ("Light bleeding") and of the vssm and msm READMEs; shared by
// tests/render/test_accuracy.cpp and tests/render/test_msm.cpp.
#pragma once
#include "image/image.h"

#include <cstddef>

namespace rtlab {

// Both one channel of the same size; the reference's mask selects surface pixels. 0 when the
// reference has no umbra.
inline double meanUmbraVisibility(const Image& reference, const Image& visibility) {
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < reference.pixelCount(); ++i) {
    if (reference.mask[i] < 0.5f || reference.pixels[i] > 0.0f) continue;
    sum += visibility.pixels[i];
    ++n;
  }
  return n ? sum / double(n) : 0.0;
}

} // namespace rtlab
