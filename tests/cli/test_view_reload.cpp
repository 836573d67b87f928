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

// A copy of shaders/ under dir/data, for RTLAB_DATA_DIR; returns dir/data.
fs::path copyShaders(const fs::path& dir) {
  const fs::path data = dir / "data";
  fs::create_directories(data);
  fs::copy(fs::path(RTLAB_SOURCE_DIR) / "shaders", data / "shaders", fs::copy_options::recursive);
  return data;
}

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The file with a syntax error inserted as its line 3.
void breakLine3(const fs::path& path, const std::string& good) {
  const std::size_t line3 = good.find('\n', good.find('\n') + 1) + 1;
  std::ofstream(path) << good.substr(0, line3) + "this is not GLSL;\n" + good.substr(line3);
}

} // namespace

TEST(ViewReload, BrokenShaderKeepsRenderingAndReportsFileLineThenRecovers) {
  ASSERT_TRUE(fs::exists(kXvfbRun)) << "install xvfb (scripts/setup.sh --test-deps)";
  const fs::path dir = freshTestDir("view");
  const fs::path data = copyShaders(dir);
  const fs::path shader = data / "shaders" / "shading" / "tonemap.frag";
  const std::string good = readText(shader);
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
  breakLine3(shader, good);
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

// A technique switched on while its shader is broken: its program never compiled, so there is no
// last good one. The viewer reports the file:line, keeps showing the last picture, and goes on.
TEST(ViewReload, TechniqueWithABrokenShaderReportsItAndKeepsTheLastPicture) {
  ASSERT_TRUE(fs::exists(kXvfbRun)) << "install xvfb (scripts/setup.sh --test-deps)";
  const fs::path dir = freshTestDir("view");
  const fs::path data = copyShaders(dir);
  const fs::path shader = data / "shaders" / "pcf" / "visibility.frag";
  breakLine3(shader, readText(shader));
  auto file = [&](const char* name) { return (dir / name).string(); };
  const nlohmann::json script = {{{"action", "wait"}, {"frames", 3}},
                                 {{"action", "screenshot"}, {"file", file("before.png")}},
                                 {{"action", "technique"}, {"stage", "shadow"}, {"id", "pcf"}},
                                 {{"action", "wait"}, {"frames", 5}},
                                 {{"action", "screenshot"}, {"file", file("broken.png")}},
                                 {{"action", "report"}, {"file", file("report.json")}},
                                 {{"action", "quit"}}};
  std::vector<std::string> args = kViewSize;
  args.push_back("--script");
  args.push_back(writeScript(dir / "script.json", script));
  const auto r = runView(args, {"RTLAB_DATA_DIR=" + data.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto report = readJson(dir / "report.json");
  ASSERT_EQ(report["shader_errors"].size(), 1u) << report["shader_errors"].dump();
  const std::string message = report["shader_errors"][0];
  EXPECT_NE(message.find("pcf/visibility.frag:3"), std::string::npos) << message;
  EXPECT_EQ(report["gl_errors"], 0);
  // The picture right of the panel is the last one rendered (no shadow technique), not black.
  EXPECT_LT(regionDiff(rtlab::readImage(file("broken.png")), rtlab::readImage(file("before.png")), 0.5, 1.0),
            0.5 / 255.0);
}

// `rtlab view --exercise DIR` (docs/exercises.md): the student's files replace the shipped ones and
// are the ones watched. The untouched folder runs (its stub: everything lit); a syntax error in the
// student's file is reported as that file:line while the viewer goes on; the solution written into
// the file then shows the shadows without restarting.
TEST(ViewReload, ExerciseFolderIsWatchedAndItsErrorsNameTheStudentsFile) {
  ASSERT_TRUE(fs::exists(kXvfbRun)) << "install xvfb (scripts/setup.sh --test-deps)";
  const fs::path dir = freshTestDir("view");
  const fs::path folder = dir / "student";
  ASSERT_EQ(runProcess(RTLAB_BINARY, {"exercise", "new", "shadow_map", "--out", folder.string()}).exitCode, 0);
  const std::string rel = "shaders/shadow/common/shadow_space.glsl";
  const fs::path shader = folder / rel;
  const std::string stub = readText(shader);
  auto file = [&](const char* name) { return (dir / name).string(); };
  const int phaseFrames = 80;
  const nlohmann::json script = {{{"action", "wait"}, {"frames", 3}},
                                 {{"action", "report"}, {"file", file("before.json")}},
                                 {{"action", "screenshot"}, {"file", file("before.png")}},
                                 {{"action", "wait"}, {"frames", phaseFrames}},
                                 {{"action", "report"}, {"file", file("broken.json")}},
                                 {{"action", "wait"}, {"frames", phaseFrames}},
                                 {{"action", "report"}, {"file", file("after.json")}},
                                 {{"action", "screenshot"}, {"file", file("after.png")}},
                                 {{"action", "quit"}}};
  std::vector<std::string> args = kViewSize;
  args.insert(args.end(), {"--exercise", folder.string(), "--script", writeScript(dir / "script.json", script)});
  ProcessResult result;
  std::thread viewer([&] { result = runView(args); });
  const bool started = waitFor(dir / "before.json", 60);
  breakLine3(shader, stub);
  const bool broke = waitFor(dir / "broken.json", 60);
  fs::copy_file(fs::path(RTLAB_SOURCE_DIR) / rel, shader, fs::copy_options::overwrite_existing);
  viewer.join();
  ASSERT_TRUE(started && broke) << result.err;
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto before = readJson(dir / "before.json"), broken = readJson(dir / "broken.json"),
             after = readJson(dir / "after.json");
  EXPECT_TRUE(before["shader_errors"].empty()) << before["shader_errors"].dump();
  ASSERT_FALSE(broken["shader_errors"].empty()) << "the student's broken file was not reported";
  const std::string message = broken["shader_errors"][0];
  EXPECT_NE(message.find(shader.string() + ":3"), std::string::npos) << message;
  EXPECT_TRUE(after["shader_errors"].empty()) << after["shader_errors"].dump();
  // With the solution in place the shadows appear: the picture right of the panel changed.
  EXPECT_GT(regionDiff(rtlab::readImage(file("after.png")), rtlab::readImage(file("before.png")), 0.5, 1.0), 1.0 / 255.0);
}
