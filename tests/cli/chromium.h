// Headless Chromium for the page tests (the sweep report, the showcase): a screenshot and the
// DOM after load, console messages, and whether a screenshot is blank. scripts/test.sh installs
// chromium (setup.sh --test-deps); its absence fails the test everywhere, with a message that
// says so when CI is set (docs/testing.md, "Skip conditions").
#pragma once
#include "process.h"

#include "image/image.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace rtlab::test {

inline const std::filesystem::path kChromium = "/usr/bin/chromium";

// The caller fails (ASSERT_TRUE) when this returns false: a page left unchecked is not a pass.
inline bool chromiumAvailable(std::string& why) {
  if (std::filesystem::exists(kChromium)) return true;
  why = std::getenv("CI") ? "CI is set but /usr/bin/chromium is missing (scripts/setup.sh --test-deps)"
                          : "no /usr/bin/chromium (scripts/setup.sh --test-deps installs it)";
  return false;
}

// Loads `page` (a file) in headless Chromium; with `screenshot`, writes a PNG of the window, else
// dumps the DOM after load to the result's stdout. `profile`: a fresh user-data folder.
inline ProcessResult runChromium(const std::filesystem::path& page, const std::filesystem::path& profile,
                                 const std::filesystem::path& screenshot = {}) {
  std::vector<std::string> args = {"--headless", "--no-sandbox", "--disable-gpu", "--enable-logging=stderr", "--v=0",
                                   "--no-first-run", "--user-data-dir=" + profile.string(), "--window-size=1200,1400"};
  args.push_back(screenshot.empty() ? "--dump-dom" : "--screenshot=" + screenshot.string());
  args.push_back("file://" + std::filesystem::absolute(page).string());
  return runProcess(kChromium.string(), args, 90);
}

// Console messages in Chromium's stderr (a page with none logs nothing).
inline std::vector<std::string> consoleMessages(const std::string& err) {
  std::vector<std::string> out;
  std::istringstream in(err);
  std::string line;
  while (std::getline(in, line))
    if (line.find("CONSOLE") != std::string::npos) out.push_back(line);
  return out;
}

// A page with text, a chart and images has pixels that vary and some dark ones.
inline void expectNotBlank(const rtlab::Image& image) {
  ASSERT_GT(image.width, 100);
  double sum = 0, sumSq = 0;
  for (float v : image.pixels) sum += v, sumSq += double(v) * v;
  const double n = double(image.pixels.size());
  const double variance = sumSq / n - (sum / n) * (sum / n);
  EXPECT_GT(variance, 1e-3) << "the screenshot is blank";
  std::size_t dark = 0;
  for (float v : image.pixels) dark += v < 0.5f;
  EXPECT_GT(dark, image.pixels.size() / 200) << "no text or chart drawn";
}

} // namespace rtlab::test
