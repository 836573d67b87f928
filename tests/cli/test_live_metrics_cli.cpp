// The viewer's live metrics (framework/reference/live_metrics.h) against the real
// `rtlab compare REFERENCE.exr FRAME.exr --json`: the same images, written as the viewer's
// reference and frame would be, give the same figures, bit for bit (EXR stores the floats
// exactly and --json writes doubles with round-trip precision).
#include "process.h"

#include "image/image.h"
#include "reference/live_metrics.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <random>

namespace fs = std::filesystem;

namespace {

// A w x h image of `channels` with a smooth pattern plus noise, a mask with a few background
// pixels (at positions depending on `seed`) and, optionally, one NaN.
rtlab::Image testImage(int w, int h, int channels, unsigned seed, bool withNan) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> noise(-0.1f, 0.1f);
  rtlab::Image im(w, h, channels);
  im.mask.assign(im.pixelCount(), 1.0f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < channels; ++c)
        im.at(x, y, c) = 0.3f + 0.4f * float(x) / float(w) + 0.1f * c + noise(rng);
  for (int k = 0; k < 5; ++k) {
    const std::size_t i = rng() % im.pixelCount();
    im.mask[i] = 0.0f;
    for (int c = 0; c < channels; ++c)
      im.pixels[i * std::size_t(channels) + std::size_t(c)] = 0.0f;
  }
  if (withNan) im.pixels[std::size_t(channels) * 7] = std::nanf("");
  return im;
}

void expectFigure(const nlohmann::json& j, const char* key, double value) {
  if (!std::isfinite(value)) {
    EXPECT_TRUE(j[key].is_null()) << key;
    return;
  }
  EXPECT_EQ(j[key].get<double>(), value) << key;
}

TEST(LiveMetricsCli, EqualToCompareOnTheSameImages) {
  const fs::path dir = fs::path(RTLAB_TEST_TMP) / "cli_live_metrics";
  fs::remove_all(dir);
  fs::create_directories(dir);
  struct Case {
    int refChannels, frameChannels;
  };
  for (const Case c : {Case{1, 1}, Case{3, 3}, Case{3, 1}}) {
    rtlab::ProgressiveSnapshot reference;
    reference.image = testImage(40, 24, c.refChannels, 1, false);
    reference.samples = 16;
    reference.generation = 3;
    const rtlab::Image frame = testImage(40, 24, c.frameChannels, 2, true);
    const std::string refPath = (dir / "reference.exr").string(), framePath = (dir / "frame.exr").string();
    rtlab::writeImage(refPath, reference.image);
    rtlab::writeImage(framePath, frame);

    const rtlab::LiveMetrics live = rtlab::computeLiveMetrics(frame, reference);
    ASSERT_TRUE(live.ready) << live.reason;
    const auto r = rtlab::test::runProcess(RTLAB_BINARY, {"compare", refPath, framePath, "--json"}, 60);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    SCOPED_TRACE(std::to_string(c.refChannels) + " vs " + std::to_string(c.frameChannels) + " channels");
    expectFigure(j, "rmse", live.metrics.rmse);
    expectFigure(j, "ssim", live.metrics.ssim);
    expectFigure(j, "flip", live.metrics.flip);
    expectFigure(j, "max_abs", live.metrics.maxAbs);
    ASSERT_TRUE(live.metrics.psnr.has_value());
    expectFigure(j, "psnr", *live.metrics.psnr);
    EXPECT_EQ(j["nan_count"].get<std::size_t>(), live.metrics.nanCount);
    EXPECT_EQ(j["valid_pixels"].get<std::size_t>(), live.metrics.validPixels);
    EXPECT_EQ(live.metrics.nanCount, 1u);
    EXPECT_LT(live.metrics.validPixels, 40u * 24u - 5u); // both masks and the NaN count
  }
}

} // namespace
