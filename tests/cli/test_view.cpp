// The window path: `rtlab view` under a virtual X display (Xvfb). A screenshot after 5 frames
// shows the side panel beside the frame: where the panel is (the left part of the window) the
// image differs from a headless `rtlab render` of the frame; the frame's region, rendered at its
// own size, matches `rtlab render` at that size within 2/255 per channel on average (the same
// passes; only the context differs). Without a display the command exits 4 naming xvfb-run; a
// script's "quit" exits 0.
#include "view_helpers.h"

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using namespace rtlab::test;

TEST(View, ScreenshotAfterFiveFramesShowsThePanelBesideTheFrame) {
  ASSERT_TRUE(fs::exists(kXvfbRun)) << "install xvfb (scripts/setup.sh --test-deps)";
  const fs::path dir = freshTestDir("view");
  const std::string shot = (dir / "window.png").string(), headless = (dir / "headless.png").string();
  const std::vector<std::string> frame = {"--scene", "contact", "-t", "shadow_map"};
  std::vector<std::string> view = frame;
  view.insert(view.end(), kViewSize.begin(), kViewSize.end());
  for (const char* a : {"--frames", "5", "--screenshot"})
    view.push_back(a);
  view.push_back(shot);
  auto r = runView(view);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const rtlab::Image a = rtlab::readImage(shot);
  ASSERT_EQ(a.width, 320);
  ASSERT_EQ(a.height, 180);
  // The panel is 22 font sizes wide, at most half the window (viewer/viewer_layout.h): at 320x180
  // the left half. Its text and frames make the left third differ strongly from the frame
  // rendered at the window's size; the right half is the frame rendered at 160x180.
  r = renderAt(frame, 320, 180, headless);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_GT(regionDiff(a, rtlab::readImage(headless), 0.0, 0.33), 0.03) << "no panel in the window's screenshot";
  r = renderAt(frame, 160, 180, headless);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const rtlab::Image region = crop(a, nlohmann::json::array({160, 0, 160, 180}));
  // Rows below 0.45: at 160 pixels wide the info overlay wraps to three lines at the top.
  EXPECT_LT(regionDiff(region, rtlab::readImage(headless), 0.0, 1.0, 0.45, 1.0), 2.0 / 255.0)
      << "the frame beside the panel differs from rtlab render at its size";
}

TEST(View, WithoutDisplayExits4SuggestingXvfbRun) {
  auto r = runProcess("/usr/bin/env", {"-u", "DISPLAY", "-u", "WAYLAND_DISPLAY", RTLAB_BINARY, "view", "--frames", "1",
                                       "--screenshot", (fs::path(RTLAB_TEST_TMP) / "never.png").string()});
  EXPECT_EQ(r.exitCode, 4) << r.err;
  EXPECT_NE(r.err.find("rtlab: error:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("xvfb-run"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("rtlab render"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(fs::path(RTLAB_TEST_TMP) / "never.png"));
}

TEST(View, QuitActionExitsZeroWithoutGlErrors) {
  ASSERT_TRUE(fs::exists(kXvfbRun)) << "install xvfb (scripts/setup.sh --test-deps)";
  const fs::path dir = freshTestDir("view");
  const std::string script = writeScript(dir / "quit.json", nlohmann::json::parse(R"([
    {"action": "wait", "frames": 3},
    {"action": "report", "file": ")" + (dir / "report.json").string() + R"("},
    {"action": "quit"},
    {"action": "wait", "frames": 1000000}])"));
  std::vector<std::string> args = kViewSize;
  args.push_back("--script");
  args.push_back(script);
  auto r = runView(args);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto report = readJson(dir / "report.json");
  EXPECT_EQ(report["schema"], 1);
  EXPECT_GE(report["frames"].get<int>(), 3);
  EXPECT_EQ(report["gl_errors"], 0);
  EXPECT_TRUE(report["shader_errors"].empty());
}

// Scripts and bookmarks are checked before the window opens, so a bad file fails the same way with
// or without a display (here: without), and nothing is run.
TEST(View, BadScriptOrBookmarksFailBeforeTheWindowOpens) {
  const fs::path dir = freshTestDir("view");
  std::ofstream(dir / "bad_action.json") << R"([{"action": "fly"}])";
  std::ofstream(dir / "bad_value.json") << R"([{"action": "set", "key": "pcf.radius", "value": 99}])";
  std::ofstream(dir / "bookmarks.json") << R"({"schema": 1, "bookmarks": [{"name": "x", "techniques": ["nope"]}]})";
  auto view = [&](std::vector<std::string> args) {
    args.insert(args.begin(), {"-u", "DISPLAY", "-u", "WAYLAND_DISPLAY", RTLAB_BINARY, "view"});
    return runProcess("/usr/bin/env", args);
  };
  auto r = view({"--script", (dir / "missing.json").string()});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  r = view({"--script", (dir / "bad_action.json").string()});
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_NE(r.err.find("fly"), std::string::npos) << r.err;
  r = view({"--script", (dir / "bad_value.json").string()});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("pcf.radius"), std::string::npos) << r.err;
  r = view({"--bookmarks", (dir / "bookmarks.json").string()});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("nope"), std::string::npos) << r.err;
}
