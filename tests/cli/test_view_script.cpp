// Scripted viewer runs (`rtlab view --script`, docs/viewer-scripts.md) change the picture the way
// the panels would: switching the shadow technique off removes the shadows, a parameter edit
// shows in the next frame and in the preset saved afterwards, the debug view replaces the frame,
// a snapshot wipe shows the frozen picture right of the divider, and a bookmark applies its
// techniques and parameters. Screenshots are compared right of the panel (the panel takes at
// most the left half of the window; the frame's region is the right half at 320x180).
#include "view_helpers.h"

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using namespace rtlab::test;

TEST(ViewScript, TechniqueOffParameterPresetDebugViewSnapshotAndBookmark) {
  ASSERT_TRUE(fs::exists(kXvfbRun)) << "install xvfb (scripts/setup.sh --test-deps)";
  const fs::path dir = freshTestDir("view");
  auto file = [&](const char* name) { return (dir / name).string(); };
  std::ofstream(dir / "bookmarks.json") << R"({"schema": 1, "bookmarks": [
    {"name": "Hard shadow, small map", "techniques": ["shadow_map"], "params": {"shadow.resolution": 512}}]})";
  const nlohmann::json script = {{{"action", "technique"}, {"stage", "shadow"}, {"id", "pcf"}},
                                 {{"action", "wait"}, {"frames", 3}},
                                 {{"action", "screenshot"}, {"file", file("on.png")}},
                                 {{"action", "technique"}, {"stage", "shadow"}, {"id", "off"}},
                                 {{"action", "wait"}, {"frames", 2}},
                                 {{"action", "screenshot"}, {"file", file("off.png")}},
                                 {{"action", "technique"}, {"stage", "shadow"}, {"id", "pcf"}},
                                 {{"action", "set"}, {"key", "pcf.radius"}, {"value", 24}},
                                 {{"action", "wait"}, {"frames", 2}},
                                 {{"action", "screenshot"}, {"file", file("radius.png")}},
                                 {{"action", "save_preset"}, {"file", file("preset.json")}},
                                 {{"action", "view"}, {"aov", "visibility"}, {"mode", "full"}, {"false_color", true}},
                                 {{"action", "wait"}, {"frames", 2}},
                                 {{"action", "screenshot"}, {"file", file("view.png")}},
                                 {{"action", "view"}, {"mode", "off"}},
                                 {{"action", "set"}, {"key", "tonemap.exposure"}, {"value", 4}},
                                 {{"action", "wait"}, {"frames", 2}},
                                 {{"action", "screenshot"}, {"file", file("bright.png")}},
                                 {{"action", "snapshot"}},
                                 {{"action", "wait"}, {"frames", 1}},
                                 {{"action", "reset"}, {"key", "tonemap.exposure"}},
                                 {{"action", "compare"}, {"mode", "snapshot"}, {"divider", 0.75}},
                                 {{"action", "wait"}, {"frames", 2}},
                                 {{"action", "screenshot"}, {"file", file("wipe.png")}},
                                 {{"action", "compare"}, {"mode", "off"}},
                                 {{"action", "bookmark"}, {"index", 0}},
                                 {{"action", "wait"}, {"frames", 2}},
                                 {{"action", "report"}, {"file", file("report.json")}},
                                 {{"action", "quit"}}};
  std::vector<std::string> args = kViewSize;
  for (const std::string& a : {std::string("--script"), writeScript(dir / "script.json", script),
                               std::string("--bookmarks"), file("bookmarks.json")})
    args.push_back(a);
  const auto r = runView(args);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto img = [&](const char* name) { return rtlab::readImage(file(name)); };
  const rtlab::Image on = img("on.png"), off = img("off.png"), radius = img("radius.png");
  // Shadows cover a few percent of the frame right of the panel; a change of at least 0.5/255
  // on average there means whole shadow regions changed (identical frames differ by 0).
  EXPECT_GT(regionDiff(on, off, 0.5, 1.0), 0.5 / 255.0) << "switching the shadow off did not change the picture";
  EXPECT_GT(regionDiff(on, radius, 0.5, 1.0), 0.5 / 255.0) << "pcf.radius 24 did not change the picture";
  const auto preset = readJson(dir / "preset.json");
  EXPECT_EQ(preset["params"]["pcf.radius"], 24.0);
  EXPECT_EQ(preset["techniques"], nlohmann::json::array({"pcf"}));
  // The false-color visibility view replaces the shaded frame.
  EXPECT_GT(regionDiff(img("view.png"), radius, 0.5, 1.0), 0.05);
  // The wipe: left of the divider the current frame (exposure back to 1), right of it the
  // snapshot taken at exposure 4. The divider at 0.75 of the frame's region (x 160..320) is at
  // 0.875 of the window; the rows leave out the wipe's labels at the region's bottom.
  const rtlab::Image wipe = img("wipe.png"), bright = img("bright.png");
  EXPECT_LT(regionDiff(wipe, radius, 0.5, 0.85, 0.3, 0.7), 2.0 / 255.0);
  EXPECT_LT(regionDiff(wipe, bright, 0.9, 1.0, 0.3, 0.7), 2.0 / 255.0);
  // Exposure 4 brightens the floor; the black background stays black, hence the mean of 0.02.
  EXPECT_GT(regionDiff(bright, radius, 0.9, 1.0, 0.3, 0.7), 0.02) << "exposure 4 should brighten the frame";
  const auto report = readJson(dir / "report.json");
  EXPECT_EQ(report["techniques"], nlohmann::json::array({"shadow_map"}));
  EXPECT_EQ(report["params"]["shadow.resolution"], 512);
  EXPECT_EQ(report["bookmark"], 0);
  EXPECT_EQ(report["gl_errors"], 0);
}
