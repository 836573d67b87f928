// Shared by the ao techniques' render tests (ssao, hbao): one frame's `ao` AOV and the ray-traced
// reference of the same surface points, their metrics, and the error of "no AO" (ao = 1) as the
// yardstick; averages over chosen pixels.
#pragma once
#include "render_fixture.h"

#include "image/image.h"
#include "image/metrics.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace rtlab::test {

struct AoMeasurement {
  TestFrame frame;
  Image ao;        // the technique's ao AOV (mask = surface)
  Image reference; // (1/pi) * integral of V cos within ao.radius, ray traced
  Metrics metrics; // ao against the reference over surface pixels
  Metrics noAo;    // ao = 1 on every surface pixel against the reference
  int glErrors = 0;
};

// Renders `technique` (may be "" for none) with `sets` and, when spp > 0, the reference.
AoMeasurement measureAo(const std::string& scene, const std::string& technique, const std::vector<std::string>& sets,
                        int size, int spp);

// Mean of a one-channel image over the (2r+1)^2 pixels around (x, y) that are surface pixels;
// -1 if none.
double meanAround(const Image& image, int x, int y, int r);

// Fraction of surface pixels whose value is at least `threshold`.
double fractionAtLeast(const Image& image, float threshold);

// Number of pixels whose value is NaN or infinite.
std::size_t nonFiniteCount(const Image& image);

// True if every non-surface pixel (mask 0) holds exactly 0.
bool backgroundIsZero(const Image& image);

} // namespace rtlab::test
