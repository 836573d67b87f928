// `rtlab render --stats` reports the exposure readout of the frame's linear `color` (docs/cli.md
// "--stats"): the values match those computed here from the written EXR by the definition, and do
// not depend on which AOV is written.
#include "image/image.h"
#include "process.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using rtlab::test::runProcess;

namespace {

fs::path testDir(const std::string& name) {
  fs::path d = fs::path(RTLAB_TEST_TMP) / "cli-exposure" / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

nlohmann::json renderStats(const fs::path& dir, const std::string& aov, const std::string& out) {
  const auto r = runProcess(RTLAB_BINARY, {"render", "--scene", "glow", "--size", "96x54", "--aov", aov, "--out",
                                          (dir / out).string(), "--stats", (dir / (out + ".json")).string()});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  std::ifstream in(dir / (out + ".json"));
  return nlohmann::json::parse(in);
}

TEST(CliRender, StatsReportTheExposureOfTheLinearColor) {
  const fs::path dir = testDir("glow");
  const nlohmann::json j = renderStats(dir, "color", "c.exr");
  ASSERT_TRUE(j.contains("exposure")) << j.dump();
  const auto& e = j.at("exposure");

  // The definition, on the EXR the same run wrote: every pixel, background included.
  const rtlab::Image img = rtlab::readImage((dir / "c.exr").string());
  ASSERT_EQ(img.channels, 3);
  double sumLog = 0.0, maxL = 0.0;
  for (std::size_t i = 0; i < img.pixelCount(); ++i) {
    const float* p = &img.pixels[i * 3];
    const double l = std::max(0.0, 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]);
    sumLog += std::log(1e-4 + l);
    maxL = std::max(maxL, l);
  }
  const double average = std::exp(sumLog / double(img.pixelCount()));
  EXPECT_NEAR(e.at("log_average_luminance").get<double>(), average, 1e-6 * average);
  EXPECT_NEAR(e.at("max_luminance").get<double>(), maxL, 1e-6 * maxL);
  EXPECT_NEAR(e.at("key_exposure").get<double>(), 0.18 / average, 1e-6 * 0.18 / average);
  EXPECT_EQ(e.at("pixels"), img.pixelCount());
  EXPECT_EQ(e.at("non_finite_pixels"), 0);
  // glow's brightest emitter has luma 1e4 (docs/scene-format.md).
  EXPECT_NEAR(maxL, 1e4, 10.0);

  // Written with another AOV, the readout is still that of `color`.
  const nlohmann::json v = renderStats(dir, "depth", "d.pfm");
  EXPECT_EQ(v.at("exposure"), e);
}

} // namespace
