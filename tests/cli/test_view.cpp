// The window path: `rtlab view` under a virtual X display (Xvfb). A screenshot after 5 frames
// shows the side panel over the frame: where the panel is (the left part of the window) the
// image differs from a headless `rtlab render` of the same frame; right of it the two match
// within 2/255 per channel on average (the same passes; only the context differs). Without a
// display the command exits 4 naming xvfb-run; a script's "quit" exits 0.
#include "view_helpers.h"

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using namespace rtlab::test;

TEST(View, ScreenshotAfterFiveFramesShowsThePanelOverTheFrame) {
  ASSERT_TRUE(fs::exists(kXvfbRun)) << "install xvfb (scripts/setup.sh --test-deps)";
  const fs::path dir = freshTestDir("view");
  const std::string shot = (dir / "window.png").string(), headless = (dir / "headless.png").string();
  std::vector<std::string> frame = {"--scene", "contact", "-t", "shadow_map"};
  frame.insert(frame.end(), kViewSize.begin(), kViewSize.end());
  std::vector<std::string> view = frame;
  for (const char* a : {"--frames", "5", "--screenshot"})
    view.push_back(a);
  view.push_back(shot);
  auto r = runView(view);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::vector<std::string> render = {"render"};
  render.insert(render.end(), frame.begin(), frame.end());
  render.push_back("--out");
  render.push_back(headless);
  r = runProcess(RTLAB_BINARY, render, 120);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const rtlab::Image a = rtlab::readImage(shot), b = rtlab::readImage(headless);
  ASSERT_EQ(a.width, 320);
  ASSERT_EQ(a.height, 180);
  // The panel is at most 45% of the window's width (ui/panels.cpp): its text and frames make the
  // left third differ strongly; the right 45% is the frame alone.
  EXPECT_GT(regionDiff(a, b, 0.0, 0.33), 0.03) << "no panel in the window's screenshot";
  EXPECT_LT(regionDiff(a, b, 0.55, 1.0), 2.0 / 255.0) << "the frame beside the panel differs from rtlab render";
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
