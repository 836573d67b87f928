// image/metrics: identical images give rmse 0, ssim 1, flip 0 and no psnr; synthetic pairs give
// hand-computed rmse, psnr and ssim; NaN/Inf pixels and masked pixels are counted and excluded;
// FLIP's properties (black vs white near 1, small noise small, symmetric, monotonic); heat maps.
#include "image/image.h"
#include "image/metrics.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace rtlab;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

Image constant(int w, int h, int c, float v) {
  Image im(w, h, c);
  std::fill(im.pixels.begin(), im.pixels.end(), v);
  return im;
}

// A smooth pattern with edges, in [0,1]: something for SSIM and FLIP to look at.
Image pattern(int w, int h, int c) {
  Image im(w, h, c);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int k = 0; k < c; ++k) {
        const float wave = 0.5f + 0.3f * std::sin(0.31f * x + 0.17f * y + 1.3f * k);
        im.at(x, y, k) = (x / 8 + y / 8) % 2 ? wave : 0.25f * wave;
      }
  return im;
}

Image withNoise(const Image& in, float amplitude, unsigned seed) {
  Image out = in;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-amplitude, amplitude);
  for (float& v : out.pixels) v = std::clamp(v + u(rng), 0.0f, 1.0f);
  return out;
}

} // namespace

TEST(Metrics, IdenticalImages) {
  for (int c : {1, 3}) {
    const Image a = pattern(40, 30, c);
    const Metrics m = computeMetrics(a, a);
    EXPECT_EQ(m.rmse, 0.0);
    EXPECT_FALSE(m.psnr.has_value());
    EXPECT_NEAR(m.ssim, 1.0, 1e-12);
    EXPECT_EQ(m.flip, 0.0);
    EXPECT_EQ(m.maxAbs, 0.0);
    EXPECT_EQ(m.nanCount, 0u);
    EXPECT_EQ(m.validPixels, 40u * 30u);
  }
}

TEST(Metrics, ConstantOffsetHandComputed) {
  // Every value differs by 0.1: MSE 0.01, RMSE 0.1, PSNR 10 log10(1 / 0.01) = 20 dB.
  const Metrics m = computeMetrics(constant(8, 6, 3, 0.5f), constant(8, 6, 3, 0.6f));
  EXPECT_NEAR(m.rmse, 0.1, 1e-6);
  ASSERT_TRUE(m.psnr.has_value());
  EXPECT_NEAR(*m.psnr, 20.0, 1e-4);
  EXPECT_NEAR(m.maxAbs, 0.1, 1e-6);
  // Constant images: variances 0, SSIM = (2 mx my + C1) / (mx^2 + my^2 + C1), C1 = 1e-4.
  EXPECT_NEAR(m.ssim, (2 * 0.5 * 0.6 + 1e-4) / (0.25 + 0.36 + 1e-4), 1e-6);
}

TEST(Metrics, SinglePixelDifferenceHandComputed) {
  // 2x2 one-channel, one pixel off by 1: MSE 1/4, RMSE 0.5, PSNR 10 log10(4) = 6.0206 dB.
  Image a = constant(2, 2, 1, 0.0f), b = a;
  b.at(1, 0, 0) = 1.0f;
  const Metrics m = computeMetrics(a, b);
  EXPECT_NEAR(m.rmse, 0.5, 1e-9);
  EXPECT_NEAR(*m.psnr, 10.0 * std::log10(4.0), 1e-9);
  EXPECT_NEAR(m.maxAbs, 1.0, 1e-9);
}

TEST(Metrics, RmseRunsOverEveryChannel) {
  // One pixel of two, channel differences (0.1, 0.2, 0.2): MSE = (0.01 + 0.04 + 0.04) / 6.
  Image a = constant(2, 1, 3, 0.2f), b = a;
  b.at(0, 0, 0) += 0.1f;
  b.at(0, 0, 1) += 0.2f;
  b.at(0, 0, 2) -= 0.2f;
  const Metrics m = computeMetrics(a, b);
  const double mse = (0.01 + 0.04 + 0.04) / 6.0;
  EXPECT_NEAR(m.rmse, std::sqrt(mse), 1e-6);
  EXPECT_NEAR(*m.psnr, 10.0 * std::log10(1.0 / mse), 1e-4);
  EXPECT_NEAR(m.maxAbs, 0.2, 1e-6);
}

TEST(Metrics, NanAndInfPixelsCountedAndExcluded) {
  Image a = constant(6, 5, 3, 0.5f), b = constant(6, 5, 3, 0.6f);
  a.at(1, 1, 0) = kNaN;   // NaN in A
  b.at(4, 2, 2) = kInf;   // Inf in B
  b.at(0, 4, 1) = -kInf;
  a.at(3, 3, 1) = kNaN;   // non-finite in both at one pixel: counted once
  b.at(3, 3, 0) = kNaN;
  const Metrics m = computeMetrics(a, b);
  EXPECT_EQ(m.nanCount, 4u);
  EXPECT_EQ(m.validPixels, 30u - 4u);
  EXPECT_NEAR(m.rmse, 0.1, 1e-6);
  EXPECT_NEAR(*m.psnr, 20.0, 1e-4);
  EXPECT_NEAR(m.maxAbs, 0.1, 1e-6);
  EXPECT_TRUE(std::isfinite(m.ssim));
  EXPECT_TRUE(std::isfinite(m.flip));
  // The figures equal those of the same pair without the bad pixels' neighbourhood effects:
  // uniform images give uniform per-pixel SSIM.
  EXPECT_NEAR(m.ssim, computeMetrics(constant(6, 5, 3, 0.5f), constant(6, 5, 3, 0.6f)).ssim, 1e-9);
  EXPECT_NEAR(m.flip, computeMetrics(constant(6, 5, 3, 0.5f), constant(6, 5, 3, 0.6f)).flip, 1e-6);
}

TEST(Metrics, MaskExcludesBackground) {
  Image a = pattern(16, 12, 1), b = a;
  a.mask.assign(a.pixelCount(), 1.0f);
  for (int x = 0; x < 16; ++x) {
    a.mask[std::size_t(11) * 16 + x] = 0.0f; // bottom row is background
    b.at(x, 11, 0) = 7.0f;                   // and holds garbage in B
  }
  Metrics m = computeMetrics(a, b);
  EXPECT_EQ(m.validPixels, 16u * 11u);
  EXPECT_EQ(m.rmse, 0.0);
  EXPECT_FALSE(m.psnr.has_value());
  EXPECT_NEAR(m.ssim, 1.0, 1e-12);
  EXPECT_EQ(m.flip, 0.0);
  // A mask on either input counts.
  m = computeMetrics(b, a);
  EXPECT_EQ(m.validPixels, 16u * 11u);
  EXPECT_EQ(m.rmse, 0.0);
}

TEST(Metrics, NoValidPixelsGivesNoFigures) {
  const Metrics m = computeMetrics(constant(3, 3, 1, kNaN), constant(3, 3, 1, 0.0f));
  EXPECT_EQ(m.validPixels, 0u);
  EXPECT_EQ(m.nanCount, 9u);
  EXPECT_TRUE(std::isnan(m.rmse));
  EXPECT_FALSE(m.psnr.has_value());
  const auto j = metricsToJson(m);
  EXPECT_TRUE(j["rmse"].is_null());
  EXPECT_TRUE(j["ssim"].is_null());
  EXPECT_TRUE(j["flip"].is_null());
  EXPECT_EQ(j["valid_pixels"], 0);
}

TEST(Metrics, DifferentSizesAreInputErrors) {
  try {
    computeMetrics(constant(4, 4, 1, 0.0f), constant(4, 5, 1, 0.0f));
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::Input);
    EXPECT_NE(std::string(e.what()).find("4x5"), std::string::npos) << e.what();
  }
  EXPECT_THROW(absoluteErrorImage(constant(4, 4, 1, 0.0f), constant(5, 4, 1, 0.0f)), Error);
}

TEST(Metrics, DifferentChannelCountsCompareLuminance) {
  Image color(4, 4, 3), gray(4, 4, 1);
  for (std::size_t i = 0; i < color.pixelCount(); ++i) {
    const float r = 0.1f * (i % 5), g = 0.05f * (i % 7), b = 0.3f;
    color.pixels[3 * i] = r;
    color.pixels[3 * i + 1] = g;
    color.pixels[3 * i + 2] = b;
    gray.pixels[i] = 0.2126f * r + 0.7152f * g + 0.0722f * b;
  }
  const Metrics m = computeMetrics(color, gray);
  EXPECT_NEAR(m.rmse, 0.0, 1e-6);
  EXPECT_NEAR(m.ssim, 1.0, 1e-6);
  EXPECT_NEAR(m.flip, 0.0, 1e-3);
}

TEST(Metrics, JsonSchema) {
  const Image a = pattern(8, 8, 1);
  auto j = metricsToJson(computeMetrics(a, a));
  std::vector<std::string> keys;
  for (const auto& [k, v] : j.items()) keys.push_back(k);
  EXPECT_EQ(keys, (std::vector<std::string>{"schema", "rmse", "psnr", "ssim", "flip", "max_abs", "nan_count",
                                            "valid_pixels"}));
  EXPECT_EQ(j["schema"], 1);
  EXPECT_TRUE(j["psnr"].is_null());
  j = metricsToJson(computeMetrics(a, withNoise(a, 0.1f, 3)));
  EXPECT_TRUE(j["psnr"].is_number());
}

TEST(Metrics, AbsoluteErrorImage) {
  Image a = constant(3, 2, 3, 0.5f), b = a;
  b.at(0, 0, 0) = 0.8f; // mean over channels: 0.1
  a.at(2, 1, 1) = kNaN;
  const Image e = absoluteErrorImage(a, b);
  ASSERT_EQ(e.channels, 1);
  EXPECT_NEAR(e.at(0, 0, 0), 0.1f, 1e-6);
  EXPECT_EQ(e.at(1, 0, 0), 0.0f);
  EXPECT_EQ(e.at(2, 1, 0), 0.0f);
  ASSERT_TRUE(e.hasMask());
  EXPECT_EQ(e.mask[5], 0.0f);
  EXPECT_EQ(e.mask[0], 1.0f);
}

TEST(Ssim, NoiseLowersSsimAndIsSymmetric) {
  const Image a = pattern(48, 48, 1);
  const double weak = computeMetrics(a, withNoise(a, 0.02f, 1)).ssim;
  const double strong = computeMetrics(a, withNoise(a, 0.2f, 1)).ssim;
  EXPECT_LT(weak, 1.0);
  EXPECT_GT(weak, 0.9);
  EXPECT_LT(strong, weak);
  EXPECT_GE(strong, -1.0);
  const Image n = withNoise(a, 0.2f, 1);
  EXPECT_NEAR(computeMetrics(a, n).ssim, computeMetrics(n, a).ssim, 1e-12);
}

TEST(Ssim, WindowIgnoresMaskedPixels) {
  // Two pairs identical on the valid pixels, different on masked ones: the same SSIM.
  Image a = pattern(32, 32, 1), b = withNoise(a, 0.1f, 5);
  a.mask.assign(a.pixelCount(), 1.0f);
  for (int y = 10; y < 20; ++y)
    for (int x = 10; x < 20; ++x) a.mask[std::size_t(y) * 32 + x] = 0.0f;
  Image a2 = a, b2 = b;
  for (int y = 10; y < 20; ++y)
    for (int x = 10; x < 20; ++x) {
      a2.at(x, y, 0) = 0.9f;
      b2.at(x, y, 0) = (x + y) % 2 ? 0.0f : 1.0f;
    }
  EXPECT_NEAR(computeMetrics(a, b).ssim, computeMetrics(a2, b2).ssim, 1e-12);
}

TEST(Ssim, StructureMattersMoreThanTheSameRmse) {
  // Wang et al.'s point: equal MSE, different SSIM. A constant shift keeps structure; noise does not.
  const Image a = pattern(48, 48, 1);
  Image shifted = a;
  for (float& v : shifted.pixels) v += 0.05f;
  Image noisy = a;
  std::mt19937 rng(7);
  for (float& v : noisy.pixels) v += (rng() & 1) ? 0.05f : -0.05f;
  const Metrics ms = computeMetrics(a, shifted), mn = computeMetrics(a, noisy);
  EXPECT_NEAR(ms.rmse, mn.rmse, 1e-6);
  EXPECT_GT(ms.ssim, mn.ssim);
}

TEST(Flip, PixelsPerDegreeOfDefaultViewing) {
  // 0.7 m from a 0.7 m wide 3840-pixel display: 3840 * pi / 180 = 67.02 pixels per degree.
  EXPECT_NEAR(pixelsPerDegree(MetricsOptions{}), 67.0206, 1e-3);
}

TEST(Flip, BlackVersusWhiteIsNearOne) {
  for (int c : {1, 3}) {
    const double f = computeMetrics(constant(32, 32, c, 0.0f), constant(32, 32, c, 1.0f)).flip;
    EXPECT_GT(f, 0.95) << c;
    EXPECT_LE(f, 1.0) << c;
  }
}

TEST(Flip, SmallNoiseSmallLargeNoiseLarge) {
  const Image a = pattern(64, 64, 3);
  const double small = computeMetrics(a, withNoise(a, 0.01f, 2)).flip;
  const double medium = computeMetrics(a, withNoise(a, 0.1f, 2)).flip;
  const double large = computeMetrics(a, withNoise(a, 0.5f, 2)).flip;
  EXPECT_GT(small, 0.0);
  EXPECT_LT(small, 0.05);
  EXPECT_LT(small, medium);
  EXPECT_LT(medium, large);
}

TEST(Flip, Symmetric) {
  const Image a = pattern(40, 40, 3), b = withNoise(a, 0.2f, 9);
  EXPECT_NEAR(computeMetrics(a, b).flip, computeMetrics(b, a).flip, 1e-6);
}

TEST(Flip, ErrorMapInUnitRangeAndMatchesMean) {
  Image a = pattern(24, 20, 3), b = withNoise(a, 0.3f, 4);
  a.at(3, 3, 0) = kNaN;
  const Image map = flipErrorImage(a, b);
  ASSERT_EQ(map.channels, 1);
  ASSERT_TRUE(map.hasMask());
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < map.pixelCount(); ++i) {
    EXPECT_GE(map.pixels[i], 0.0f);
    EXPECT_LE(map.pixels[i], 1.0f);
    if (map.mask[i] > 0.5f) sum += map.pixels[i], ++n;
  }
  EXPECT_EQ(n, map.pixelCount() - 1);
  EXPECT_NEAR(sum / n, computeMetrics(a, b).flip, 1e-6);
}

TEST(Flip, EdgeShiftIsSeen) {
  // A misplaced edge (a shadow boundary one pixel off) is a feature difference FLIP reports.
  Image a = constant(32, 32, 1, 0.0f), b = a;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      a.at(x, y, 0) = x < 16 ? 0.0f : 1.0f;
      b.at(x, y, 0) = x < 17 ? 0.0f : 1.0f;
    }
  const double f = computeMetrics(a, b).flip;
  EXPECT_GT(f, 0.01);
  EXPECT_LT(f, 0.5);
}

TEST(Flip, DisplayEncodedInputsAreDecoded) {
  // The same display values read as linear (3 channels) or as sRGB-encoded give different FLIP,
  // and a 1-channel image is read as display gray either way.
  const Image a = constant(16, 16, 3, 0.2f), b = constant(16, 16, 3, 0.3f);
  MetricsOptions display;
  display.displayEncoded = true;
  EXPECT_NE(computeMetrics(a, b).flip, computeMetrics(a, b, display).flip);
  const Image g1 = constant(16, 16, 1, 0.2f), g2 = constant(16, 16, 1, 0.3f);
  EXPECT_NEAR(computeMetrics(g1, g2).flip, computeMetrics(a, b, display).flip, 1e-5);
}

TEST(Metrics, HeatmapColours) {
  Image e(3, 1, 1);
  e.pixels = {0.0f, 0.5f, 2.0f};
  e.mask = {1.0f, 1.0f, 0.0f};
  const Image h = errorHeatmap(e, 1.0f);
  ASSERT_EQ(h.channels, 3);
  EXPECT_NEAR(h.at(0, 0, 0), 0.001462f, 1e-6); // magma(0): near black
  EXPECT_NEAR(h.at(1, 0, 0), 0.713175f, 2e-3);  // magma(0.5): table entries 127 and 128
  EXPECT_NEAR(h.at(1, 0, 2), 0.476245f, 2e-3);
  EXPECT_EQ(h.at(2, 0, 1), 0.5f);               // masked: gray
  e.mask.clear();
  const Image top = errorHeatmap(e, 1.0f);
  EXPECT_NEAR(top.at(2, 0, 1), 0.991438f, 1e-6); // clamped to magma(1)
}

TEST(Flip, DependsOnlyOnValidPixels) {
  // Background pixels (mask 0) with other values, in either image, change no figure.
  Image a = pattern(40, 32, 3), b = withNoise(a, 0.1f, 6);
  a.mask.assign(a.pixelCount(), 1.0f);
  for (int y = 0; y < 32; ++y)
    for (int x = 25; x < 40; ++x) a.mask[std::size_t(y) * 40 + x] = 0.0f;
  Image a2 = a, b2 = b;
  for (int y = 0; y < 32; ++y)
    for (int x = 25; x < 40; ++x)
      for (int k = 0; k < 3; ++k) {
        a2.at(x, y, k) = 0.0f;
        b2.at(x, y, k) = 1.0f;
      }
  const Metrics m = computeMetrics(a, b), m2 = computeMetrics(a2, b2);
  EXPECT_EQ(m.validPixels, 25u * 32u);
  EXPECT_NEAR(m.flip, m2.flip, 1e-9);
  EXPECT_NEAR(m.ssim, m2.ssim, 1e-12);
  EXPECT_NEAR(m.rmse, m2.rmse, 1e-12);
}
