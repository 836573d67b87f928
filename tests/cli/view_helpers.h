// Helpers of the viewer tests (test_view*.cpp): run `rtlab view` under Xvfb (xvfb-run, installed
// by scripts/setup.sh --test-deps), write scripts, read reports, and compare image regions.
#pragma once
#include "process.h"
#include "test_util.h"

#include "image/image.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace rtlab::test {

inline constexpr const char* kXvfbRun = "/usr/bin/xvfb-run";
// The window of every viewer test: small, so llvmpipe draws a frame in milliseconds.
inline const std::vector<std::string> kViewSize = {"--size", "320x180"};

// `xvfb-run -a [env NAME=VALUE...] rtlab view ARGS...`
inline ProcessResult runView(const std::vector<std::string>& args, const std::vector<std::string>& env = {},
                             int timeoutSeconds = 120) {
  std::vector<std::string> all = {"-a"};
  if (!env.empty()) {
    all.push_back("/usr/bin/env");
    all.insert(all.end(), env.begin(), env.end());
  }
  all.push_back(RTLAB_BINARY);
  all.push_back("view");
  all.insert(all.end(), args.begin(), args.end());
  return runProcess(kXvfbRun, all, timeoutSeconds);
}

inline std::string writeScript(const std::filesystem::path& path, const nlohmann::json& actions) {
  std::ofstream(path) << actions.dump(1);
  return path.string();
}

inline nlohmann::json readJson(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// Mean absolute difference per channel value over the columns [x0, x1) and rows [y0, y1)
// (fractions of the width and height; rows from the top). The default rows leave out the top
// quarter, where the info overlay (frame time, live metrics) sits on the right.
inline double regionDiff(const Image& a, const Image& b, double x0, double x1, double y0 = 0.3, double y1 = 1.0) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.channels, b.channels);
  const int from = int(x0 * a.width), to = int(x1 * a.width);
  double sum = 0;
  std::size_t n = 0;
  for (int y = int(y0 * a.height); y < int(y1 * a.height); ++y)
    for (int x = from; x < to; ++x)
      for (int c = 0; c < a.channels; ++c, ++n)
        sum += std::abs(a.at(x, y, c) - b.at(x, y, c));
  return n ? sum / double(n) : 0.0;
}

// The pixels of `image` in the rectangle [x, y, width, height] (pixels, rows from the top): the
// frame's region of a viewer screenshot (the report's layout.frame).
inline Image crop(const Image& image, const nlohmann::json& rect) {
  const int x0 = rect[0], y0 = rect[1], w = rect[2], h = rect[3];
  Image out(w, h, image.channels);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < image.channels; ++c)
        out.at(x, y, c) = image.at(x0 + x, y0 + y, c);
  return out;
}

// `rtlab render ARGS... --size WxH --out OUT` (exit code checked by the caller).
inline ProcessResult renderAt(std::vector<std::string> args, int width, int height, const std::string& out) {
  args.insert(args.begin(), "render");
  for (const std::string& a : {std::string("--size"), std::to_string(width) + "x" + std::to_string(height),
                               std::string("--out"), out})
    args.push_back(a);
  return runProcess(RTLAB_BINARY, args, 120);
}

// The gray level of a one-channel image, replicated, to compare with a 3-channel screenshot.
inline Image grayToRgb(const Image& gray) {
  Image rgb(gray.width, gray.height, 3);
  for (int y = 0; y < gray.height; ++y)
    for (int x = 0; x < gray.width; ++x)
      for (int c = 0; c < 3; ++c)
        rgb.at(x, y, c) = std::clamp(gray.at(x, y, 0), 0.0f, 1.0f);
  return rgb;
}

} // namespace rtlab::test
