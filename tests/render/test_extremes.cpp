// Numerical stability at the extremes, generated from the registry so every technique added later
// is covered without new test code: each numeric parameter of each technique, and each parameter
// of its stage, at its min and at its max (every choice of an enum, both values of a bool) renders
// finite values in the stage's AOV and in color, with zero GL errors, within the budget below.
//
// Budget (stated, checked per render): GPU resources at most 640 MiB and at most 60 s of wall
// time on llvmpipe. The largest cases: msm at shadow.resolution 4096 (a 4096^2 RGBA32F moment map,
// its RGBA32F summed-area table and a 24-bit depth buffer: 256 + 256 + 64 = 576 MiB), and a
// 4096^2 32F cube shadow map (6 * 64 MiB = 384 MiB).
#include "render_fixture.h"

#include "frame/registry.h"
#include "frame/stages.h"
#include "params/param_set.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

namespace rtlab {
namespace {

constexpr std::size_t kMaxResourceBytes = std::size_t(640) << 20;
constexpr double kMaxSeconds = 60.0;
constexpr int kSize = 64;

struct ExtremeCase {
  std::string technique, key, value;
};

std::vector<std::string> extremeValues(const ParamSpec& spec) {
  switch (spec.type) {
  case ParamType::Bool: return {"false", "true"};
  case ParamType::Enum: return spec.choices;
  case ParamType::Float:
  case ParamType::Int: return {formatParamValue(spec, ParamValue::scalar(spec.min)), formatParamValue(spec, ParamValue::scalar(spec.max))};
  default: return {}; // vec3/color parameters are positions and colors, not approximation knobs
  }
}

std::vector<ExtremeCase> allCases() {
  std::vector<ExtremeCase> cases;
  for (const auto& entry : TechniqueRegistry::instance().entries()) {
    std::vector<ParamSpec> specs = entry.info.params;
    const StageInfo* stage = findStage(entry.info.stage);
    specs.insert(specs.end(), stage->params.begin(), stage->params.end());
    for (const auto& spec : specs)
      for (const auto& v : extremeValues(spec)) cases.push_back({entry.info.id, spec.key, v});
    if (specs.empty()) cases.push_back({entry.info.id, "", ""}); // still render it once
  }
  return cases;
}

std::string caseName(const ::testing::TestParamInfo<ExtremeCase>& info) {
  std::string n = info.param.technique + "_" + info.param.key + "_" + info.param.value;
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
}

class Extremes : public ::testing::TestWithParam<ExtremeCase> {};

TEST_P(Extremes, RendersFiniteWithoutGlErrors) {
  const ExtremeCase& c = GetParam();
  const auto& entry = TechniqueRegistry::instance().get(c.technique);
  const std::string stageAov = findStage(entry.info.stage)->output;
  std::vector<std::string> sets;
  if (!c.key.empty()) sets.push_back(c.key + "=" + c.value);
  TestFrame f = makeTestFrame(entry.info.showcaseScene, c.technique, sets, kSize, kSize);
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::string> aovs = {"color"};
  if (stageAov != "color") aovs.push_back(stageAov);
  TestRender r = renderTestFrame(f, aovs);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.glErrors, 0);
  EXPECT_LE(r.stats.resourceBytes(), kMaxResourceBytes);
  EXPECT_LE(seconds, kMaxSeconds);
  for (const auto& aov : aovs) {
    const Image img = r.renderer->readAov(aov);
    std::size_t bad = 0;
    for (float v : img.pixels) bad += std::isfinite(v) ? 0 : 1;
    EXPECT_EQ(bad, 0u) << aov << " has non-finite values";
  }
}

INSTANTIATE_TEST_SUITE_P(Registry, Extremes, ::testing::ValuesIn(allCases()), caseName);

} // namespace
} // namespace rtlab
