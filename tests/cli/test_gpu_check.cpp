// The moment techniques under both headless platforms, and scripts/gpu-check.sh (issue 19;
// docs/performance.md, "GPU check (scripts/gpu-check.sh)"). One process has one GL platform, so
// the binary runs twice.
#include "process.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using rtlab::test::runProcess;

namespace gpu_check_test {
namespace {

fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::path(RTLAB_TEST_TMP) / "cli_gpu_check" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

} // namespace
} // namespace gpu_check_test
using namespace gpu_check_test;

// vssm and msm (with and without the precision keys) on contact and stacked give the same
// visibility through EGL and OSMesa: both are llvmpipe here, so the bound is tight — RMSE at most
// 1e-6 and no pixel more than 1e-4 apart (measured: identical). On a GPU the same comparison is
// scripts/gpu-check.sh's, with its tolerances.
TEST(GpuCheck, MomentTechniquesMatchUnderEglAndOsmesa) {
  const fs::path dir = freshDir("platforms");
  struct Variant {
    std::string technique, set;
  };
  const std::vector<Variant> variants = {{"vssm", ""}, {"msm", ""}, {"vssm", "vssm.sat_bits=64"},
                                         {"msm", "msm.centred=true"}};
  for (const char* scene : {"contact", "stacked"})
    for (const Variant& v : variants) {
      std::string images[2];
      int k = 0;
      for (const char* backend : {"egl", "osmesa"}) {
        images[k] = (dir / (std::string(scene) + "_" + v.technique + "_" + std::to_string(k) + ".exr")).string();
        std::vector<std::string> args = {"render", "--backend", backend, "--scene", scene, "-t", v.technique,
                                         "--aov", "visibility", "--size", "160x90", "--out", images[k]};
        if (!v.set.empty()) args.insert(args.end(), {"--set", v.set});
        const auto r = runProcess(RTLAB_BINARY, args, 120);
        ASSERT_EQ(r.exitCode, 0) << backend << ": " << r.err;
        ++k;
      }
      const auto c = runProcess(RTLAB_BINARY, {"compare", images[0], images[1], "--json", "--over", "1e-4"}, 60);
      ASSERT_EQ(c.exitCode, 0) << c.err;
      const auto j = nlohmann::json::parse(c.out);
      const std::string what = std::string(scene) + " " + v.technique + " " + v.set;
      EXPECT_LE(j["rmse"].get<double>(), 1e-6) << what;
      EXPECT_EQ(j["over"]["pixels"], 0) << what;
      EXPECT_EQ(j["nan_count"], 0) << what;
    }
}

// The script's self-test (EGL and OSMesa both llvmpipe) passes and prints a row per technique; a
// tolerance file without a technique's row fails (exit 1) naming it; a bad option is a usage
// error (exit 2).
TEST(GpuCheck, ScriptSelfTestTableAndFailures) {
  const fs::path dir = freshDir("script");
  const std::string script = std::string(RTLAB_SOURCE_DIR) + "/scripts/gpu-check.sh";
  const std::vector<std::string> common = {script, "--rtlab", RTLAB_BINARY, "--self-test", "--size", "96x54",
                                           "--techniques", "shadow_map,msm"};
  std::vector<std::string> args(common.begin() + 1, common.end());
  args.insert(args.end(), {"--out", (dir / "ok").string()});
  const auto ok = runProcess(common[0], args, 300);
  ASSERT_EQ(ok.exitCode, 0) << ok.out << ok.err;
  EXPECT_NE(ok.out.find("| msm | visibility | contact |"), std::string::npos) << ok.out;
  EXPECT_NE(ok.out.find("| shadow_map | visibility | contact |"), std::string::npos) << ok.out;
  EXPECT_NE(ok.out.find("0 of 2 techniques failed"), std::string::npos) << ok.out;

  const fs::path partial = dir / "partial.tsv";
  std::ofstream(partial) << "# only shadow_map\nshadow_map 0.002 0.5 0.001\n";
  args = std::vector<std::string>(common.begin() + 1, common.end());
  args.insert(args.end(), {"--out", (dir / "partial").string(), "--tolerances", partial.string()});
  const auto missing = runProcess(common[0], args, 300);
  EXPECT_EQ(missing.exitCode, 1) << missing.out << missing.err;
  EXPECT_NE(missing.out.find("| msm | visibility | contact | - | - | - | FAIL: no tolerance"), std::string::npos)
      << missing.out;

  const auto bad = runProcess(common[0], {"--size", "big"}, 60);
  EXPECT_EQ(bad.exitCode, 2) << bad.err;
}

// --timings: one row per technique with its own passes (from the stats' pass list) and the
// framework's, on its showcase scene; the size and frame count are the options'.
TEST(GpuCheck, TimingsListEachTechniquesPasses) {
  const fs::path dir = freshDir("timings");
  const std::string script = std::string(RTLAB_SOURCE_DIR) + "/scripts/gpu-check.sh";
  const auto r = runProcess(script, {"--rtlab", RTLAB_BINARY, "--timings", (dir / "t").string(), "--size", "64x36",
                                     "--frames", "1", "--techniques", "pcss,bloom", "--out", (dir / "work").string()},
                            300);
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("64x36, 1 frames, timing cpu-finish"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| pcss | contact | shadow.depth "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("pcss.visibility "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| bloom | glow | bloom.bright "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("bloom.composite "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("gbuffer "), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(dir / "t" / "pcss.json"));
  EXPECT_TRUE(fs::exists(dir / "t" / "timings.md"));
  EXPECT_EQ(runProcess(script, {"--timings", (dir / "u").string(), "--frames", "0"}, 60).exitCode, 2);
}

// --render-tests: the binary's XML report read back, its failures named (exit 1), a passing filter
// (exit 0), a missing binary a usage error (exit 2). The failing binary is a stand-in script that
// writes gtest's report format.
TEST(GpuCheck, RenderTestsReportPassesAndNamesFailures) {
  const fs::path dir = freshDir("render_tests");
  const std::string script = std::string(RTLAB_SOURCE_DIR) + "/scripts/gpu-check.sh";
  const auto ok = runProcess(script, {"--rtlab", RTLAB_BINARY, "--render-tests", RTLAB_RENDER_TESTS,
                                      (dir / "ok").string(), "--filter", "Context.ParseBackend"}, 300);
  ASSERT_EQ(ok.exitCode, 0) << ok.out << ok.err;
  EXPECT_NE(ok.out.find(": 1 tests, 0 failed"), std::string::npos) << ok.out;

  const fs::path fake = dir / "fake_tests.sh";
  std::ofstream(fake) << "#!/bin/sh\n"
                         "for a in \"$@\"; do case $a in --gtest_output=xml:*) out=${a#--gtest_output=xml:} ;; esac; done\n"
                         "cat > \"$out\" <<'X'\n"
                         "<testsuites tests=\"2\" time=\"0.1\"><testsuite name=\"S\">"
                         "<testcase classname=\"S\" name=\"Passes\"/>"
                         "<testcase classname=\"S\" name=\"Breaks\"><failure message=\"x\"/></testcase>"
                         "</testsuite></testsuites>\nX\nexit 1\n";
  fs::permissions(fake, fs::perms::owner_all);
  const auto bad = runProcess(script, {"--rtlab", RTLAB_BINARY, "--render-tests", fake.string(), (dir / "bad").string()}, 120);
  EXPECT_EQ(bad.exitCode, 1) << bad.out << bad.err;
  EXPECT_NE(bad.out.find("2 tests, 1 failed"), std::string::npos) << bad.out;
  EXPECT_NE(bad.out.find("FAILED S.Breaks"), std::string::npos) << bad.out;

  EXPECT_EQ(runProcess(script, {"--render-tests", (dir / "missing").string()}, 60).exitCode, 2);
}
