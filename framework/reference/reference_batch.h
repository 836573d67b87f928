// One batch of the CPU reference: `spp` samples per pixel of one quantity over a range of 16x16
// tiles, run in parallel with TBB (in whatever task arena calls it), each pixel's samples keyed by
// (seed, pixel) so that the result does not depend on scheduling or thread count. renderReference
// (reference.h) is one batch over every tile; ProgressiveReference (progressive_reference.h)
// averages many batches of independent seeds and stops between tiles when cancelled.
#pragma once
#include "image/image.h"
#include "reference/estimators.h"
#include "reference/progress.h"
#include "reference/surfaces.h"
#include "scene/scene.h"

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

namespace rtlab::reference {

enum class Quantity { Visibility, Ao, Indirect };

// "visibility", "ao", "indirect"; Error(Usage) naming the choices otherwise.
Quantity parseQuantity(const std::string& aov);
int channelCount(Quantity quantity); // 3 for indirect, 1 otherwise

// The checks every reference job makes before it casts a ray: Error(Usage) for a sample count
// outside kReferenceMinSpp..kReferenceMaxSpp (the message names it as `sppName`), a non-positive
// AO radius for ao, no light for visibility; Error(Internal) for surface data of inconsistent size.
void checkReferenceJob(Quantity quantity, int spp, const std::string& sppName, float aoRadius,
                       const std::vector<Light>& lights, const SurfaceData& surfaces);

constexpr int kTileSize = 16;
int tileCount(int width, int height);

struct BatchSpec {
  Quantity quantity = Quantity::Ao;
  int spp = 1;
  std::uint32_t seed = 1;
  bool stratified = true;
  glm::vec3 eye{0.0f}; // the camera position the surfaces were seen from (secondary rays start toward it)
};

// Tiles [firstTile, lastTile) of `image` (surfaces' size, channelCount channels, mask of one value
// per pixel): each surface pixel gets the mean of spec.spp samples and mask 1; background pixels
// are left alone (the caller zeroes them). A tile starts only while `cancel` (may be null) is
// false: returns false when cancelled, with the image partly written. Adds the rays cast to
// `rays` and the pixels done to `progress` (may be null).
bool renderBatch(const EstimatorContext& ctx, const SurfaceData& surfaces, const BatchSpec& spec, Image& image,
                 int firstTile, int lastTile, const std::atomic<bool>* cancel, std::atomic<std::uint64_t>& rays,
                 ProgressBar* progress);

} // namespace rtlab::reference
