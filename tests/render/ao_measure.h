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

// Views of issue 6 set with camera.*. kGrazingView: contact's ground (y = 0, |x|,|z| <= 6) from
// 0.3 above it, looking along -z at the ground's far edge: only ground (down to a few degrees of
// grazing) and sky are in view. kCreaseView: cornell's floor (y = 0) meeting the back wall
// (z = -2.75) at x = 1.2, where the nearest block and side wall are more than 1 away.
inline const std::vector<std::string> kGrazingView = {"camera.position=2.5,0.3,-2", "camera.target=2.5,0,-6"};
inline const std::vector<std::string> kCreaseView = {"camera.position=1.2,1.3,-0.8", "camera.target=1.2,0.2,-2.75"};

// a followed by b.
std::vector<std::string> joined(std::vector<std::string> a, const std::vector<std::string>& b);

// The technique's ao on kGrazingView, once per entry of `variants` (a set added to the view):
// at least 98% of the floor at ao >= 0.95, no GL error, sky pixels 0 with mask 0.
void expectGrazingFloorClear(const std::string& technique, const std::vector<std::string>& variants);

// ao around the floor points of kCreaseView at distances 0.05, 0.2, 0.35, 0.6, 0.75 from the
// wall (ao.radius is 0.5 there), each printed beside the reference.
std::vector<double> creaseProfile(const AoMeasurement& m);

// The crease's shape in creaseProfile(m): occluded next to the wall (below 0.85), rising with the
// distance (up to 0.02 of noise between the 2nd and 3rd points), and at least `beyondRadius` at
// the two points beyond ao.radius.
void expectCreaseShape(const AoMeasurement& m, double beyondRadius);

// Each case (sets on cornell, 64x64) renders finite ao in [0, 1] without GL errors and with sky
// pixels 0; and ao.radius = 0.01 leaves at least 99% of the surface at ao >= 0.99.
void expectExtremesFinite(const std::string& technique, const std::vector<std::vector<std::string>>& cases);

// The debug views <technique>.raw, .blurred and .pattern render at full and half resolution on
// cornell (64x48, with `sets`): blurred equals the stage output, and the pattern marks taps.
void expectDebugViewsRender(const std::string& technique, const std::vector<std::string>& sets);

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
