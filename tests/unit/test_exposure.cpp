// The exposure readout (image/exposure.h): L̄ = exp(mean(log(1e-4 + L))) over every pixel with Rec.
// 709 luminance, the largest L, and 0.18 / L̄; non-finite pixels left out and counted.
#include "image/exposure.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace rtlab {
namespace {

Image grey(int w, int h, float v) {
  Image img(w, h, 3);
  for (float& p : img.pixels) p = v;
  return img;
}

void setPixel(Image& img, int x, int y, float r, float g, float b) {
  img.at(x, y, 0) = r;
  img.at(x, y, 1) = g;
  img.at(x, y, 2) = b;
}

TEST(Exposure, UniformMiddleGreyNeedsExposureOne) {
  const ExposureReadout r = measureExposure(grey(8, 4, 0.18f));
  EXPECT_NEAR(r.logAverageLuminance, 0.18 + 1e-4, 1e-7);
  EXPECT_NEAR(r.maxLuminance, 0.18, 1e-7);
  EXPECT_NEAR(r.keyExposure, 0.18 / (0.18 + 1e-4), 1e-6);
  EXPECT_EQ(r.pixels, 32u);
  EXPECT_EQ(r.nonFinite, 0u);
}

TEST(Exposure, IsTheGeometricMeanOfDeltaPlusLuminance) {
  // One pixel of luminance 1e4 and three black ones: the mean of the logs, not of the values.
  Image img = grey(2, 2, 0.0f);
  setPixel(img, 1, 0, 1e4f, 1e4f, 1e4f);
  const ExposureReadout r = measureExposure(img);
  const double expected = std::exp((std::log(1e4 + 1e-4) + 3.0 * std::log(1e-4)) / 4.0); // 1e-2, about
  EXPECT_NEAR(r.logAverageLuminance, expected, 1e-9);
  EXPECT_NEAR(r.logAverageLuminance, 0.01, 1e-6);
  EXPECT_DOUBLE_EQ(r.maxLuminance, 1e4);
  EXPECT_NEAR(r.keyExposure, 0.18 / expected, 1e-6);
}

TEST(Exposure, LuminanceUsesRec709Weights) {
  for (int c = 0; c < 3; ++c) {
    Image img = grey(1, 1, 0.0f);
    img.at(0, 0, c) = 1.0f;
    const double weight[3] = {0.2126, 0.7152, 0.0722};
    EXPECT_NEAR(measureExposure(img).maxLuminance, weight[c], 1e-7) << c;
    EXPECT_NEAR(measureExposure(img).logAverageLuminance, weight[c] + 1e-4, 1e-7) << c;
  }
  Image one(1, 1, 1);
  one.pixels[0] = 2.0f; // a 1-channel image is its own luminance
  EXPECT_NEAR(measureExposure(one).maxLuminance, 2.0, 1e-7);
}

TEST(Exposure, NonFinitePixelsAreLeftOutAndCountedNegativeLuminanceIsZero) {
  Image img = grey(2, 2, 0.5f);
  setPixel(img, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f);
  setPixel(img, 1, 0, 0.0f, std::numeric_limits<float>::infinity(), 0.0f);
  setPixel(img, 0, 1, -1.0f, -1.0f, -1.0f);
  const ExposureReadout r = measureExposure(img);
  EXPECT_EQ(r.pixels, 2u);
  EXPECT_EQ(r.nonFinite, 2u);
  EXPECT_NEAR(r.logAverageLuminance, std::sqrt(1e-4 * (0.5 + 1e-4)), 1e-9);
  EXPECT_NEAR(r.maxLuminance, 0.5, 1e-7);
}

TEST(Exposure, PartialSumsEqualPixelSums) {
  // The viewer's GPU tiles arrive as partial sums: adding them gives what adding pixels gives.
  ExposureSum pixels, partials;
  for (double l : {0.0, 0.25, 3.0}) pixels.add(l);
  pixels.add(7.5);
  partials.addPartial(std::log(1e-4) + std::log(0.25 + 1e-4) + std::log(3.0 + 1e-4), 3.0, 3);
  partials.addPartial(std::log(7.5 + 1e-4), 7.5, 1);
  partials.addPartial(0.0, 0.0, 0); // an empty tile changes nothing
  EXPECT_NEAR(pixels.readout().logAverageLuminance, partials.readout().logAverageLuminance, 1e-12);
  EXPECT_EQ(pixels.readout().maxLuminance, partials.readout().maxLuminance);
  EXPECT_EQ(pixels.readout().pixels, partials.readout().pixels);
}

TEST(Exposure, AnEmptyImageReadsAsBlack) {
  const ExposureReadout r = measureExposure(Image());
  EXPECT_EQ(r.pixels, 0u);
  EXPECT_DOUBLE_EQ(r.logAverageLuminance, 1e-4);
  EXPECT_DOUBLE_EQ(r.maxLuminance, 0.0);
  EXPECT_DOUBLE_EQ(r.keyExposure, 0.18 / 1e-4);
}

} // namespace
} // namespace rtlab
