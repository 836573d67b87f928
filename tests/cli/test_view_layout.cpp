// The viewer's layout (docs/viewer.md "Window, camera and keys"): the frame has its own region
// beside the side panel and is rendered at that region's size, so in lecture mode (large text,
// a wide panel) the region of a screenshot equals a headless `rtlab render` at the region's size;
// with the panel hidden the frame fills the window; the compare wipe sits in the middle of the
// visible frame; a data view carries a colour bar; and a screenshot never shows the status line
// of the screenshot before it.
#include "view_helpers.h"

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using namespace rtlab::test;

namespace {

const std::vector<std::string> kFrame = {"--scene", "contact", "-t", "shadow_map"};

// Runs `rtlab view` on kFrame at `size` with `script`; the exit code is checked.
void view(const std::string& size, const fs::path& dir, const nlohmann::json& script,
          std::vector<std::string> extra = {}) {
  std::vector<std::string> args = kFrame;
  for (const std::string& a : {std::string("--size"), size, std::string("--script"),
                               writeScript(dir / "script.json", script)})
    args.push_back(a);
  args.insert(args.end(), extra.begin(), extra.end());
  const auto r = runView(args);
  ASSERT_EQ(r.exitCode, 0) << r.err;
}

nlohmann::json shotAndReport(const fs::path& dir, int frames = 3) {
  return {{{"action", "wait"}, {"frames", frames}},
          {{"action", "screenshot"}, {"file", (dir / "shot.png").string()}},
          {{"action", "report"}, {"file", (dir / "report.json").string()}},
          {{"action", "quit"}}};
}

nlohmann::json concat(nlohmann::json a, const nlohmann::json& b) {
  for (const auto& x : b)
    a.push_back(x);
  return a;
}

} // namespace

// Lecture mode at 640x360: the panel (30-pixel text) takes the left part; the region beside it
// is the frame alone. Rows below the top quarter (the info overlay sits at the region's top
// right) match the headless render at the region's size within 2/255 per channel on average:
// the same passes at the same size, only the context differs (as in test_view.cpp).
TEST(ViewLayout, LectureModeFrameRegionEqualsTheHeadlessRenderAtItsSize) {
  ASSERT_TRUE(fs::exists(kXvfbRun)) << "install xvfb (scripts/setup.sh --test-deps)";
  const fs::path dir = freshTestDir("view_layout");
  view("640x360", dir, concat({{{"action", "lecture"}, {"on", true}}}, shotAndReport(dir)));
  const auto report = readJson(dir / "report.json");
  ASSERT_TRUE(report.contains("layout")) << report.dump(1);
  const auto& frame = report["layout"]["frame"];
  const auto& panel = report["layout"]["panel"];
  EXPECT_GT(panel[2].get<int>(), 100) << "the lecture panel should be wide";
  EXPECT_EQ(frame[0].get<int>(), panel[2].get<int>()) << "the frame starts where the panel ends";
  EXPECT_EQ(frame[0].get<int>() + frame[2].get<int>(), 640);
  EXPECT_EQ(report["render_size"], nlohmann::json::array({frame[2], frame[3]}));
  const auto r = renderAt(kFrame, frame[2], frame[3], (dir / "headless.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const rtlab::Image shot = crop(rtlab::readImage((dir / "shot.png").string()), frame);
  EXPECT_LT(regionDiff(shot, rtlab::readImage((dir / "headless.png").string()), 0.0, 1.0), 2.0 / 255.0)
      << "the frame region differs from rtlab render at its size";
}

// "panel" off: the frame is the whole window and equals the headless render at the window's size.
TEST(ViewLayout, HiddenPanelLetsTheFrameFillTheWindow) {
  ASSERT_TRUE(fs::exists(kXvfbRun)) << "install xvfb (scripts/setup.sh --test-deps)";
  const fs::path dir = freshTestDir("view_layout");
  view("320x180", dir, concat({{{"action", "panel"}, {"on", false}}}, shotAndReport(dir)));
  const auto report = readJson(dir / "report.json");
  EXPECT_EQ(report["layout"]["frame"], nlohmann::json::array({0, 0, 320, 180}));
  EXPECT_EQ(report["layout"]["panel_shown"], false);
  const auto r = renderAt(kFrame, 320, 180, (dir / "headless.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_LT(regionDiff(rtlab::readImage((dir / "shot.png").string()),
                       rtlab::readImage((dir / "headless.png").string()), 0.0, 1.0),
            2.0 / 255.0);
}

// The wipe's divider line (display.frag draws it in (1, 0.85, 0.2)) lies at the middle of the
// visible frame for divider 0.5, not at the window's centre under the panel.
TEST(ViewLayout, WipeDividerIsInTheMiddleOfTheVisibleFrame) {
  ASSERT_TRUE(fs::exists(kXvfbRun)) << "install xvfb (scripts/setup.sh --test-deps)";
  const fs::path dir = freshTestDir("view_layout");
  view("320x180", dir,
       concat({{{"action", "snapshot"}}, {{"action", "compare"}, {"mode", "snapshot"}, {"divider", 0.5}}},
              shotAndReport(dir)));
  const auto report = readJson(dir / "report.json");
  const auto& frame = report["layout"]["frame"];
  const rtlab::Image shot = rtlab::readImage((dir / "shot.png").string());
  const int row = shot.height / 2;
  std::vector<int> divider;
  for (int x = 0; x < shot.width; ++x)
    if (shot.at(x, row, 0) > 0.95f && std::abs(shot.at(x, row, 1) - 0.85f) < 0.03f && shot.at(x, row, 2) < 0.3f)
      divider.push_back(x);
  ASSERT_FALSE(divider.empty()) << "no divider line on the middle row";
  const double middle = frame[0].get<int>() + frame[2].get<int>() / 2.0;
  EXPECT_NEAR(divider.front(), middle, 2.0);
  EXPECT_NEAR(divider.back(), middle, 2.0);
}

// A false-color debug view carries a colour bar: the report names its region, min and max, and
// the screenshot's pixels along the bar change from its left end to its right end, with the
// lightness increasing (the ramp is monotonic in lightness, display.frag).
TEST(ViewLayout, FalseColorViewHasAColourBar) {
  ASSERT_TRUE(fs::exists(kXvfbRun)) << "install xvfb (scripts/setup.sh --test-deps)";
  const fs::path dir = freshTestDir("view_layout");
  view("320x180", dir,
       concat({{{"action", "view"}, {"aov", "visibility"}, {"mode", "full"}, {"false_color", true}, {"min", 0},
                {"max", 1}}},
              shotAndReport(dir)));
  const auto report = readJson(dir / "report.json");
  ASSERT_TRUE(report["color_bar"].is_object()) << report.dump(1);
  EXPECT_EQ(report["color_bar"]["min"], 0.0);
  EXPECT_EQ(report["color_bar"]["max"], 1.0);
  const auto& bar = report["layout"]["color_bar"];
  const rtlab::Image shot = rtlab::readImage((dir / "shot.png").string());
  const int y = bar[1].get<int>() + bar[3].get<int>() / 2, x0 = bar[0], w = bar[2];
  auto luma = [&](int x) {
    return 0.2126 * shot.at(x, y, 0) + 0.7152 * shot.at(x, y, 1) + 0.0722 * shot.at(x, y, 2);
  };
  double previous = -1.0;
  int rising = 0;
  for (int i = 0; i < 8; ++i) {
    const double v = luma(x0 + 1 + i * (w - 3) / 7);
    rising += v > previous;
    previous = v;
  }
  EXPECT_EQ(rising, 8) << "the bar's lightness should rise from min to max";
  EXPECT_GT(luma(x0 + w - 2) - luma(x0 + 1), 0.5);
}

// The status line says "screenshot a.png" after a screenshot; the next screenshot must not show it.
// The panel's top rows (title, buttons, status, the Scene section) of two consecutive screenshots
// are then identical.
TEST(ViewLayout, TransientStatusStaysOutOfScreenshots) {
  ASSERT_TRUE(fs::exists(kXvfbRun)) << "install xvfb (scripts/setup.sh --test-deps)";
  const fs::path dir = freshTestDir("view_layout");
  const nlohmann::json script = {{{"action", "wait"}, {"frames", 2}},
                                 {{"action", "screenshot"}, {"file", (dir / "a.png").string()}},
                                 {{"action", "wait"}, {"frames", 2}},
                                 {{"action", "screenshot"}, {"file", (dir / "b.png").string()}},
                                 {{"action", "quit"}}};
  view("320x180", dir, script);
  const rtlab::Image a = rtlab::readImage((dir / "a.png").string()), b = rtlab::readImage((dir / "b.png").string());
  EXPECT_EQ(regionDiff(a, b, 0.0, 0.45, 0.0, 0.45), 0.0) << "the second screenshot shows a status the first does not";
}
