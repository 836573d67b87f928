// image/umbra_speckles: the deep umbra is the reference's exact zeros eroded by the given radius
// (never reaching the border or the background), and a speckle is a deep-umbra pixel above the
// threshold (or not finite).
#include "image/image.h"
#include "image/umbra_speckles.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <limits>

using namespace rtlab;

namespace {

// 20x12, lit (1) everywhere but a dark rectangle x in [4, 15], y in [2, 9] (12x8 pixels).
Image referenceWithUmbra() {
  Image im(20, 12, 1);
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 20; ++x) im.at(x, y, 0) = (x >= 4 && x <= 15 && y >= 2 && y <= 9) ? 0.0f : 1.0f;
  im.mask.assign(im.pixelCount(), 1.0f);
  return im;
}

TEST(UmbraSpeckles, ErodesTheUmbraAndCountsPixelsAboveTheThreshold) {
  const Image ref = referenceWithUmbra();
  Image vis = ref;
  // Eroded by 3: x in [7, 12], y in [5, 6]: 6x2 = 12 pixels.
  EXPECT_EQ(measureUmbraSpeckles(ref, vis).umbraPixels, 12u);
  EXPECT_EQ(measureUmbraSpeckles(ref, vis, 1).umbraPixels, 10u * 6u);
  EXPECT_EQ(measureUmbraSpeckles(ref, vis, 0).umbraPixels, 12u * 8u);
  vis.at(8, 5, 0) = 0.06f;  // a speckle in the deep umbra
  vis.at(9, 5, 0) = 0.05f;  // at the threshold: not a speckle
  vis.at(4, 2, 0) = 1.0f;   // at the umbra's edge: outside the eroded umbra
  vis.at(12, 6, 0) = std::numeric_limits<float>::quiet_NaN();
  const UmbraSpeckles s = measureUmbraSpeckles(ref, vis);
  EXPECT_EQ(s.speckles, 2u);
  EXPECT_DOUBLE_EQ(s.share(), 2.0 / 12.0);
}

TEST(UmbraSpeckles, BackgroundAndBordersAreNotUmbra) {
  Image ref(10, 10, 1); // all 0
  ref.mask.assign(ref.pixelCount(), 1.0f);
  Image vis = ref;
  EXPECT_EQ(measureUmbraSpeckles(ref, vis, 3).umbraPixels, 4u * 4u); // 3 px from every border
  ref.mask[0] = 0.0f; // a background pixel in the corner
  EXPECT_EQ(measureUmbraSpeckles(ref, vis, 3).umbraPixels, 4u * 4u - 1u);
  vis.mask[5 * 10 + 5] = 0.0f; // background in the visibility image too
  EXPECT_EQ(measureUmbraSpeckles(ref, vis, 0).umbraPixels, 100u - 2u);
  EXPECT_EQ(measureUmbraSpeckles(ref, Image(10, 10, 1), 0).speckles, 0u);
  EXPECT_EQ(measureUmbraSpeckles(Image(4, 4, 1), Image(4, 4, 1)).share(), 0.0);
}

TEST(UmbraSpeckles, RejectsMismatchedImages) {
  EXPECT_THROW(measureUmbraSpeckles(Image(4, 4, 1), Image(5, 4, 1)), Error);
  EXPECT_THROW(measureUmbraSpeckles(Image(4, 4, 3), Image(4, 4, 1)), Error);
}

} // namespace
