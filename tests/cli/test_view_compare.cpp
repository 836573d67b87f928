// Compare mode against the progressive reference (docs/viewer.md "Compare mode"): the wipe shows
// the technique's visibility left of the divider and the reference right of it, and once the
// reference has reached a sample count (waited for by samples, not by time: the reference and
// llvmpipe share the CPU) the viewer's live RMSE matches `rtlab compare` of the same frame and a
// reference of the same sample count within 10% (the two references differ only in their noise).
#include "view_helpers.h"

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using namespace rtlab::test;

TEST(ViewCompare, WipeShowsBothHalvesAndLiveRmseMatchesRtlabCompare) {
  ASSERT_TRUE(fs::exists(kXvfbRun)) << "install xvfb (scripts/setup.sh --test-deps)";
  const fs::path dir = freshTestDir("view");
  auto file = [&](const char* name) { return (dir / name).string(); };
  // A hard shadow map against a light of radius 0.5: the reference's penumbrae differ from it.
  // 480x270: the frame's region (240x270 beside the panel) leaves rows between the info overlay
  // (top) and the colour bar and wipe labels (bottom) to compare in.
  std::vector<std::string> frame = {"--scene", "contact", "-t",     "shadow_map",
                                    "--set",   "light0.radius=0.5", "--size", "480x270"};
  const nlohmann::json script = {{{"action", "compare"}, {"mode", "reference"}, {"divider", 0.55}},
                                 {{"action", "wait_samples"}, {"samples", 32}, {"timeout_s", 100}},
                                 {{"action", "screenshot"}, {"file", file("wipe.png")}},
                                 {{"action", "report"}, {"file", file("report.json")}},
                                 {{"action", "quit"}}};
  std::vector<std::string> view = frame;
  view.push_back("--script");
  view.push_back(writeScript(dir / "script.json", script));
  auto r = runView(view);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto report = readJson(dir / "report.json");
  const auto& ref = report["reference"];
  ASSERT_EQ(ref["aov"], "visibility");
  ASSERT_TRUE(ref["rmse"].is_number()) << report.dump(1);
  const int samples = ref["metrics_samples"];
  ASSERT_GE(samples, 32);
  EXPECT_EQ(report["gl_errors"], 0);

  // The same frame headless, and a reference of the sample count the viewer measured against.
  // The frame is rendered at its region's size (beside the panel): so are these.
  const auto& region = report["layout"]["frame"];
  const std::string size = std::to_string(region[2].get<int>()) + "x" + std::to_string(region[3].get<int>());
  frame.erase(std::find(frame.begin(), frame.end(), "--size"), std::find(frame.begin(), frame.end(), "--size") + 2);
  frame.push_back("--size");
  frame.push_back(size);
  std::vector<std::string> render = {"render", "--aov", "visibility", "--out", file("frame.exr")};
  render.insert(render.end(), frame.begin(), frame.end());
  r = runProcess(RTLAB_BINARY, render, 120);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::vector<std::string> reference = {
      "reference", "--aov", "visibility", "--spp", std::to_string(samples), "--out", file("reference.exr")};
  reference.insert(reference.end(), frame.begin(), frame.end());
  reference.erase(std::find(reference.begin(), reference.end(), "-t"),
                  std::find(reference.begin(), reference.end(), "-t") + 2);
  r = runProcess(RTLAB_BINARY, reference, 300);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  r = runProcess(RTLAB_BINARY, {"compare", file("reference.exr"), file("frame.exr"), "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const double expected = nlohmann::json::parse(r.out)["rmse"];
  ASSERT_GT(expected, 0.01) << "the shadow map should differ from the soft reference";
  EXPECT_NEAR(ref["rmse"].get<double>(), expected, 0.10 * expected);

  // The wipe: data shown as gray levels in [0, 1], in the frame's region. The penumbrae lie
  // around the divider (0.55 of the region), so each side is compared over a band beside it,
  // in the rows between the info overlay (top) and the colour bar and wipe labels (bottom).
  const double y0 = 0.35, y1 = 0.65;
  const rtlab::Image shot = crop(rtlab::readImage(file("wipe.png")), region);
  const rtlab::Image technique = grayToRgb(rtlab::readImage(file("frame.exr")));
  const rtlab::Image truth = grayToRgb(rtlab::readImage(file("reference.exr")));
  EXPECT_LT(regionDiff(shot, technique, 0.40, 0.54, y0, y1), regionDiff(shot, truth, 0.40, 0.54, y0, y1));
  EXPECT_LT(regionDiff(shot, technique, 0.40, 0.54, y0, y1), 2.0 / 255.0);
  EXPECT_LT(regionDiff(shot, truth, 0.56, 0.75, y0, y1), regionDiff(shot, technique, 0.56, 0.75, y0, y1));
}
