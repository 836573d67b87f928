// Hot reload (docs/viewer.md): the viewer runs on a copy of shaders/ (RTLAB_DATA_DIR); the test
// breaks a shader the frame uses while the viewer runs. The viewer keeps rendering with the last
// good program and reports the error as file:line; once the file is restored the error clears.
// The script's reports mark the phases; the test edits the file between them.
#include "view_helpers.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace fs = std::filesystem;
using namespace rtlab::test;

namespace {

// Waits for a file the viewer writes (atomically: it exists only once complete).
bool waitFor(const fs::path& path, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!fs::exists(path)) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

} // namespace

TEST(ViewReload, BrokenShaderKeepsRenderingAndReportsFileLineThenRecovers) {
  ASSERT_TRUE(fs::exists(kXvfbRun)) << "install xvfb (scripts/setup.sh --test-deps)";
  const fs::path dir = freshTestDir("view");
  const fs::path data = dir / "data";
  fs::create_directories(data);
  fs::copy(fs::path(RTLAB_SOURCE_DIR) / "shaders", data / "shaders", fs::copy_options::recursive);
  const fs::path shader = data / "shaders" / "shading" / "tonemap.frag";
  std::string good;
  {
    std::ifstream in(shader);
    good.assign(std::istreambuf_iterator<char>(in), {});
  }
  auto file = [&](const char* name) { return (dir / name).string(); };
  // Frames between the phases: enough for several reload polls (every 0.25 s) at a few ms per
  // frame; the test edits the file as soon as a phase's report appears.
  const int phaseFrames = 80;
  const nlohmann::json script = {{{"action", "technique"}, {"stage", "shadow"}, {"id", "shadow_map"}},
                                 {{"action", "wait"}, {"frames", 3}},
                                 {{"action", "report"}, {"file", file("before.json")}},
                                 {{"action", "wait"}, {"frames", phaseFrames}},
                                 {{"action", "report"}, {"file", file("broken.json")}},
                                 {{"action", "screenshot"}, {"file", file("broken.png")}},
                                 {{"action", "wait"}, {"frames", phaseFrames}},
                                 {{"action", "report"}, {"file", file("after.json")}},
                                 {{"action", "quit"}}};
  std::vector<std::string> args = kViewSize;
  args.push_back("--script");
  args.push_back(writeScript(dir / "script.json", script));
  ProcessResult result;
  std::thread viewer([&] { result = runView(args, {"RTLAB_DATA_DIR=" + data.string()}); });

  const bool started = waitFor(dir / "before.json", 60);
  // Line 3 of the file becomes a syntax error.
  const std::size_t line3 = good.find('\n', good.find('\n') + 1) + 1;
  std::ofstream(shader) << good.substr(0, line3) + "this is not GLSL;\n" + good.substr(line3);
  const bool broke = waitFor(dir / "broken.json", 60);
  std::ofstream(shader) << good; // restored
  viewer.join();
  ASSERT_TRUE(started && broke) << result.err;
  ASSERT_EQ(result.exitCode, 0) << result.err;

  const auto before = readJson(dir / "before.json"), broken = readJson(dir / "broken.json"),
             after = readJson(dir / "after.json");
  EXPECT_TRUE(before["shader_errors"].empty());
  ASSERT_FALSE(broken["shader_errors"].empty()) << "the broken shader was not reported";
  const std::string message = broken["shader_errors"][0];
  EXPECT_NE(message.find("tonemap.frag:3"), std::string::npos) << message;
  // Still rendering: frames went on, and the picture is the last good program's (not black).
  EXPECT_GE(broken["frames"].get<int>(), before["frames"].get<int>() + phaseFrames);
  const rtlab::Image shot = rtlab::readImage(file("broken.png"));
  double sum = 0;
  for (float v : shot.pixels)
    sum += v;
  EXPECT_GT(sum / double(shot.pixels.size()), 0.1);
  EXPECT_TRUE(after["shader_errors"].empty()) << after["shader_errors"].dump();
  EXPECT_EQ(after["gl_errors"], 0);
}
