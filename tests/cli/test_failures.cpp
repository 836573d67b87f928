// Failures that need the environment changed: a shader that does not compile (exit 5, the message
// names the original file and line through #include), no GL context (exit 4), and render
// outputs of a successful run (stats JSON per docs/contract.md, a saved preset that round-trips).
#include "process.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using rtlab::test::runProcess;

namespace {

fs::path testDir(const std::string& name) {
  fs::path d = fs::path(RTLAB_TEST_TMP) / "cli-env" / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// Sets an environment variable for the scope of one test.
struct ScopedEnv {
  ScopedEnv(const char* name, const std::string& value) : m_name(name) {
    if (const char* old = std::getenv(name)) m_old = old, m_had = true;
    setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (m_had) setenv(m_name, m_old.c_str(), 1);
    else unsetenv(m_name);
  }
  const char* m_name;
  std::string m_old;
  bool m_had = false;
};

TEST(CliFailures, ShaderCompileErrorNamesFileAndLine) {
  const fs::path dir = testDir("shader");
  fs::copy(fs::path(RTLAB_SOURCE_DIR) / "shaders", dir / "shaders", fs::copy_options::recursive);
  // Break an included file (common/brdf.glsl, included by lighting.frag) at a known line.
  const fs::path brdf = dir / "shaders" / "common" / "brdf.glsl";
  std::ifstream in(brdf);
  std::stringstream text;
  std::string line;
  int n = 0, broken = 0;
  while (std::getline(in, line)) {
    ++n;
    if (line.rfind("float distributionGgx", 0) == 0) {
      text << "this is not glsl;\n";
      broken = n;
    }
    text << line << "\n";
  }
  ASSERT_GT(broken, 0);
  std::ofstream(brdf) << text.str();
  ScopedEnv env("RTLAB_DATA_DIR", dir.string());
  const auto r = runProcess(RTLAB_BINARY, {"render", "--size", "16x16", "--out", (dir / "x.png").string()});
  EXPECT_EQ(r.exitCode, 5) << r.err;
  EXPECT_EQ(rtlab::test::lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("brdf.glsl:" + std::to_string(broken) + ":"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(CliFailures, NoGlContextExits4) {
  const fs::path dir = testDir("nocontext");
  // No EGL vendor library: EGL cannot initialize, and --backend egl does not fall back.
  ScopedEnv env("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/rtlab.json");
  const auto r = runProcess(RTLAB_BINARY, {"render", "--backend", "egl", "--size", "16x16", "--out", (dir / "x.png").string()});
  EXPECT_EQ(r.exitCode, 4) << r.err;
  EXPECT_EQ(rtlab::test::lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("egl"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(CliFailures, AutoFallsBackToOsMesa) {
  const fs::path dir = testDir("fallback");
  ScopedEnv env("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/rtlab.json");
  const auto r = runProcess(RTLAB_BINARY, {"render", "--size", "16x16", "--out", (dir / "x.png").string(), "--stats",
                                          (dir / "s.json").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::ifstream in(dir / "s.json");
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["backend"], "osmesa");
}

TEST(CliFailures, InterruptLeavesNoOutput) {
  // A long render interrupted after a second: exit 130, one error line, no image, no stats, and
  // no temporary file in the output folder.
  const fs::path dir = testDir("interrupt");
  const auto r = runProcess(RTLAB_BINARY, {"render", "-t", "shadow_map", "--size", "1024x1024", "--frames", "100000",
                                          "--out", (dir / "x.png").string(), "--stats", (dir / "s.json").string()},
                            120, 1000);
  EXPECT_EQ(r.exitCode, 130) << r.err;
  EXPECT_EQ(rtlab::test::lineCount(r.err), 1) << r.err;
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(CliRender, StatsFollowTheContract) {
  const fs::path dir = testDir("stats");
  const auto r = runProcess(RTLAB_BINARY, {"render", "-t", "shadow_map", "--size", "48x32", "--frames", "3", "--aov",
                                          "visibility", "--out", (dir / "v.pfm").string(), "--stats", (dir / "s.json").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::ifstream in(dir / "s.json");
  const auto j = nlohmann::json::parse(in);
  for (const char* key : {"schema", "version", "commit", "renderer", "backend", "size", "timing", "frames", "seed",
                          "frame_ms", "passes", "resources", "resource_bytes", "gl_errors", "techniques", "params"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["schema"], 1);
  EXPECT_EQ(j["size"], nlohmann::json::array({48, 32}));
  EXPECT_EQ(j["frames"], 3);
  EXPECT_EQ(j["timing"], "cpu-finish"); // llvmpipe
  EXPECT_EQ(j["gl_errors"], 0);
  EXPECT_EQ(j["techniques"], nlohmann::json::array({"shadow_map"}));
  EXPECT_EQ(j["params"]["shadow.resolution"], 2048);
  bool found = false;
  for (const auto& p : j["passes"]) {
    EXPECT_LE(p["ms_min"].get<double>(), p["ms"].get<double>());
    EXPECT_LE(p["ms"].get<double>(), p["ms_max"].get<double>());
    if (p["name"] == "shadow_map.visibility") found = p["technique"] == "shadow_map";
  }
  EXPECT_TRUE(found);
  std::size_t sum = 0;
  for (const auto& res : j["resources"]) sum += res["bytes"].get<std::size_t>();
  EXPECT_EQ(sum, j["resource_bytes"].get<std::size_t>());
  // Extension (docs/stages.md "The HDR clamp"): visibility alone needs no colour, so no pass clamped.
  EXPECT_EQ(j["hdr_clamped"], nlohmann::json::array());
  // Extension (docs/cli.md): shadow_map reports no counters.
  EXPECT_EQ(j["counters"], nlohmann::json::array());
}

TEST(CliRender, StatsCountHdrClampedPixelsPerColourPass) {
  const fs::path dir = testDir("stats_hdr");
  const auto r = runProcess(RTLAB_BINARY, {"render", "--scene", "panes", "--size", "48x32", "--out",
                                          (dir / "c.pfm").string(), "--stats", (dir / "s.json").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::ifstream in(dir / "s.json");
  const auto j = nlohmann::json::parse(in);
  std::vector<std::string> passes;
  for (const auto& c : j.at("hdr_clamped")) {
    passes.push_back(c.at("pass"));
    EXPECT_EQ(c.at("pixels"), 0) << c; // nothing in panes is brighter than 65504
  }
  EXPECT_EQ(passes, (std::vector<std::string>{"gbuffer", "lighting", "transparent"}));
}

TEST(CliRender, SavedPresetRoundTrips) {
  const fs::path dir = testDir("preset");
  const std::string p1 = (dir / "a.json").string(), p2 = (dir / "b.json").string();
  auto r = runProcess(RTLAB_BINARY, {"render", "--scene", "stacked", "-t", "shadow_map", "--set", "shadow.constant_bias=0.0035",
                                     "--set", "light0.angle=2.5", "--set", "tonemap.operator=reinhard", "--size", "16x16",
                                     "--out", (dir / "a.png").string(), "--save-preset", p1});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  r = runProcess(RTLAB_BINARY, {"render", "--preset", p1, "--size", "16x16", "--out", (dir / "b.png").string(),
                                "--save-preset", p2});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::ifstream a(p1), b(p2);
  const auto ja = nlohmann::json::parse(a), jb = nlohmann::json::parse(b);
  EXPECT_EQ(ja, jb);
  EXPECT_EQ(ja["scene"], "stacked");
  EXPECT_EQ(ja["techniques"], nlohmann::json::array({"shadow_map"}));
  EXPECT_DOUBLE_EQ(ja["params"]["shadow.constant_bias"].get<double>(), 0.0035);
  EXPECT_EQ(ja["params"]["tonemap.operator"], "reinhard");
}

} // namespace
