// The window path: `rtlab view` under a virtual X display (Xvfb) shows the same frame as a
// headless render. Its screenshot must match `rtlab render` of the same scene within 2/255 per
// channel on average (both go through the same passes; only the context differs).
#include "process.h"

#include "image/image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace fs = std::filesystem;
using rtlab::test::runProcess;

TEST(View, ScreenshotUnderXvfbMatchesHeadlessRender) {
  ASSERT_TRUE(fs::exists("/usr/bin/xvfb-run")) << "install xvfb (scripts/setup.sh --test-deps)";
  const fs::path dir = fs::path(RTLAB_TEST_TMP) / "view";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string shot = (dir / "window.png").string(), headless = (dir / "headless.png").string();
  const std::vector<std::string> frame = {"--scene", "contact", "-t", "shadow_map", "--size", "96x64"};
  std::vector<std::string> view = {"-a", RTLAB_BINARY, "view"};
  view.insert(view.end(), frame.begin(), frame.end());
  for (const char* a : {"--frames", "3", "--screenshot"}) view.push_back(a);
  view.push_back(shot);
  auto r = runProcess("/usr/bin/xvfb-run", view, 120);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::vector<std::string> render = {"render"};
  render.insert(render.end(), frame.begin(), frame.end());
  for (const char* a : {"--out"}) render.push_back(a);
  render.push_back(headless);
  r = runProcess(RTLAB_BINARY, render, 120);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const rtlab::Image a = rtlab::readImage(shot), b = rtlab::readImage(headless);
  ASSERT_EQ(a.width, 96);
  ASSERT_EQ(a.height, 64);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  double diff = 0, sum = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    diff += std::abs(a.pixels[i] - b.pixels[i]);
    sum += a.pixels[i];
  }
  EXPECT_GT(sum / double(a.pixels.size()), 0.05) << "the window's image is black";
  EXPECT_LT(diff / double(a.pixels.size()), 2.0 / 255.0);
}
