// rtlab compare through the real binary (docs/contract.md "compare --json", "Exit codes"): exit 0
// whatever the difference, the --json keys, psnr null for identical files, the mask from EXR
// alpha, and one-line errors with exit 3 (missing, invalid, different sizes) or 2 (usage).
#include "process.h"

#include "image/image.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using rtlab::test::runProcess;

namespace {

class CompareCli : public ::testing::Test {
protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    m_dir = fs::path(RTLAB_TEST_TMP) / "cli_compare" / info->name();
    fs::remove_all(m_dir);
    fs::create_directories(m_dir);
  }
  std::string path(const std::string& name) const { return (m_dir / name).string(); }

  // A w x h image with a gradient, offset by `offset`.
  std::string image(const std::string& name, int w, int h, int channels, float offset = 0.0f) const {
    rtlab::Image im(w, h, channels);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < channels; ++c) im.at(x, y, c) = 0.2f + 0.5f * x / w + 0.1f * c + offset;
    rtlab::writeImage(path(name), im);
    return path(name);
  }

  rtlab::test::ProcessResult compare(const std::vector<std::string>& args) const {
    std::vector<std::string> all = {"compare"};
    all.insert(all.end(), args.begin(), args.end());
    return runProcess(RTLAB_BINARY, all, 60);
  }

  void expectError(const std::vector<std::string>& args, int code, const std::string& mention = "") const {
    const auto r = compare(args);
    EXPECT_FALSE(r.timedOut);
    EXPECT_EQ(r.exitCode, code) << r.err;
    EXPECT_EQ(rtlab::test::lineCount(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("rtlab: error:", 0), 0u) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    if (!mention.empty()) {
      EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
    }
  }

  fs::path m_dir;
};

TEST_F(CompareCli, IdenticalFilesJson) {
  const std::string a = image("a.exr", 16, 12, 3);
  const auto r = compare({a, a, "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  std::vector<std::string> keys;
  for (const auto& [k, v] : j.items()) keys.push_back(k);
  std::sort(keys.begin(), keys.end());
  EXPECT_EQ(keys, (std::vector<std::string>{"flip", "max_abs", "nan_count", "psnr", "rmse", "schema", "ssim",
                                            "valid_pixels"}));
  EXPECT_EQ(j["schema"], 1);
  EXPECT_TRUE(j["psnr"].is_null());
  EXPECT_EQ(j["rmse"], 0.0);
  EXPECT_DOUBLE_EQ(j["ssim"].get<double>(), 1.0);
  EXPECT_EQ(j["flip"], 0.0);
  EXPECT_EQ(j["max_abs"], 0.0);
  EXPECT_EQ(j["nan_count"], 0);
  EXPECT_EQ(j["valid_pixels"], 16 * 12);
}

TEST_F(CompareCli, DifferentFilesExitZeroWithFigures) {
  // Offset 0.1 everywhere: RMSE 0.1, PSNR 20 dB.
  const auto r = compare({image("a.pfm", 16, 12, 1), image("b.pfm", 16, 12, 1, 0.1f), "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["rmse"].get<double>(), 0.1, 1e-5);
  EXPECT_NEAR(j["psnr"].get<double>(), 20.0, 1e-3);
  EXPECT_NEAR(j["max_abs"].get<double>(), 0.1, 1e-5);
  EXPECT_GT(j["flip"].get<double>(), 0.0);
  EXPECT_LT(j["ssim"].get<double>(), 1.0);
}

TEST_F(CompareCli, TextOutputOneLinePerMetric) {
  const auto r = compare({image("a.exr", 8, 8, 3), image("b.exr", 8, 8, 3, 0.05f)});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(rtlab::test::lineCount(r.out), 7) << r.out;
  for (const char* name : {"rmse", "psnr", "ssim", "flip", "max_abs", "nan_count", "valid_pixels"})
    EXPECT_NE(r.out.find(name), std::string::npos) << name << "\n" << r.out;
}

TEST_F(CompareCli, NanPixelsCountedAndMaskFromExrAlpha) {
  rtlab::Image a(4, 4, 1), b(4, 4, 1);
  for (std::size_t i = 0; i < a.pixelCount(); ++i) a.pixels[i] = b.pixels[i] = 0.5f;
  a.mask.assign(a.pixelCount(), 1.0f);
  a.mask[0] = 0.0f;   // background in A
  b.pixels[0] = 9.0f; // differs only on the background
  b.pixels[5] = std::nanf("");
  rtlab::writeImage(path("a.exr"), a);
  rtlab::writeImage(path("b.pfm"), b);
  const auto r = compare({path("a.exr"), path("b.pfm"), "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["nan_count"], 1);
  EXPECT_EQ(j["valid_pixels"], 14);
  EXPECT_EQ(j["rmse"], 0.0);
  EXPECT_TRUE(j["psnr"].is_null());
}

TEST_F(CompareCli, DifferentSizesExit3) {
  expectError({image("a.exr", 8, 8, 3), image("b.exr", 8, 9, 3)}, 3, "8x9");
}

TEST_F(CompareCli, MissingFileExit3) {
  expectError({image("a.exr", 8, 8, 3), path("nope.exr")}, 3, "nope.exr");
  expectError({path("nope.pfm"), image("b.pfm", 8, 8, 1), "--json"}, 3, "nope.pfm");
}

TEST_F(CompareCli, InvalidFileExit3) {
  std::ofstream(path("bad.exr")) << "not an exr";
  expectError({path("bad.exr"), image("b.exr", 8, 8, 3)}, 3, "bad.exr");
  std::ofstream(path("a.txt")) << "text";
  expectError({path("a.txt"), image("c.exr", 8, 8, 3)}, 3, "a.txt");
}

TEST_F(CompareCli, UsageErrorsExit2) {
  const std::string a = image("a.exr", 4, 4, 1);
  expectError({}, 2);
  expectError({a}, 2);
  expectError({a, a, a}, 2);
  expectError({a, a, "--no-such-option"}, 2, "--no-such-option");
}

TEST_F(CompareCli, Help) {
  const auto r = compare({"--help"});
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_NE(r.out.find("rtlab compare A B"), std::string::npos) << r.out;
}

// --over E: the valid pixels whose |B - A| exceeds E, counted and as a fraction of the valid ones
// (the mask from A's alpha leaves the background out); E must be a positive number.
TEST_F(CompareCli, OverCountsPixelsAboveTheThreshold) {
  rtlab::Image a(4, 4, 1), b(4, 4, 1);
  for (std::size_t i = 0; i < a.pixelCount(); ++i) a.pixels[i] = b.pixels[i] = 0.5f;
  a.mask.assign(a.pixelCount(), 1.0f);
  a.mask[0] = 0.0f;
  b.pixels[0] = 9.0f;  // background: not counted
  b.pixels[3] = 0.8f;  // over 0.1
  b.pixels[7] = 0.55f; // under 0.1
  rtlab::writeImage(path("a.exr"), a);
  rtlab::writeImage(path("b.exr"), b);
  const auto r = compare({path("a.exr"), path("b.exr"), "--json", "--over", "0.1"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["over"]["pixels"], 1);
  EXPECT_DOUBLE_EQ(j["over"]["threshold"].get<double>(), 0.1);
  EXPECT_DOUBLE_EQ(j["over"]["fraction"].get<double>(), 1.0 / 15.0);
  const auto text = compare({path("a.exr"), path("b.exr"), "--over", "0.01"});
  ASSERT_EQ(text.exitCode, 0) << text.err;
  EXPECT_NE(text.out.find("over          2 ("), std::string::npos) << text.out;
  expectError({path("a.exr"), path("b.exr"), "--over", "0"}, 2, "--over");
  expectError({path("a.exr"), path("b.exr"), "--over", "x"}, 2, "--over");
}

} // namespace
