// Numerical stability at the extremes, generated from the registry so every technique added later
// is covered without new test code. Three families of frames, each checked the same way
// (expectSoundFrame):
//  - Extremes: each numeric parameter of each technique, and each parameter of its stage, at its
//    min and at its max (every choice of an enum, both values of a bool);
//  - CombinedExtremes: every such parameter of a technique and its stage at its min at once, and
//    at its max at once (enums: first and last choice; bools: false and true);
//  - LightSize: light 0's size at 0 and at its maximum (light0.angle for a directional light,
//    light0.radius for a spot and a point light), for each technique of the stages that read it.
// A sound frame: finite values in the stage's AOV and in color, zero GL errors, within the budget
// below, and every pass the technique adds that the frame keeps ran and did GL work (draws that
// submitted vertices or dispatches that ran invocations, counted per pass by the pass timer's
// pipeline-statistics queries, frame/pass_timer.h): a pass that silently returns early fails.
//
// Budget (stated, checked per render): GPU resources at most 768 MiB and at most 60 s of wall
// time on llvmpipe. The largest cases: msm with every key at its max at once (shadow.resolution
// 4096, msm.sat_bits 64, a 16-bit moment format: 4096^2 RGBA16F moments 128 MiB, the 64-bit
// summed-area table, RGBA32UI at 2 * 4096 x 4096, 512 MiB, and a 32F depth buffer 64 MiB: 704 MiB;
// techniques/msm/README.md), msm at shadow.resolution 4096 alone (a 4096^2 RGBA32F moment map, its
// RGBA32F summed-area table and a 24-bit depth buffer: 256 + 256 + 64 = 576 MiB), and a 4096^2 32F
// cube shadow map (6 * 64 MiB = 384 MiB).
#include "render_fixture.h"

#include "frame/registry.h"
#include "frame/stages.h"
#include "params/param_set.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <map>
#include <ostream>

namespace rtlab {
namespace {

constexpr std::size_t kMaxResourceBytes = std::size_t(768) << 20;
constexpr double kMaxSeconds = 60.0;
constexpr int kSize = 64;

// The suites of this file count each pass's GL work (frame/pass_timer.h): the timers that
// renderTestFrame makes count while a suite runs, and only then (the queries wait for the GPU).
template <class Case>
class CountingWork : public ::testing::TestWithParam<Case> {
public:
  static void SetUpTestSuite() { PassTimer::setCountWorkDefault(true); }
  static void TearDownTestSuite() { PassTimer::setCountWorkDefault(false); }
};

// The parameters of a technique and of its stage that have a range or choices (vec3/color
// parameters are positions and colors, not approximation knobs).
std::vector<ParamSpec> knobsOf(const TechniqueInfo& info) {
  std::vector<ParamSpec> specs;
  const StageInfo* stage = findStage(info.stage);
  std::vector<ParamSpec> all = info.params;
  all.insert(all.end(), stage->params.begin(), stage->params.end());
  for (const auto& spec : all)
    if (spec.type == ParamType::Bool || spec.type == ParamType::Enum || spec.type == ParamType::Float ||
        spec.type == ParamType::Int)
      specs.push_back(spec);
  return specs;
}

std::string extremeValue(const ParamSpec& spec, bool max) {
  switch (spec.type) {
  case ParamType::Bool: return max ? "true" : "false";
  case ParamType::Enum: return max ? spec.choices.back() : spec.choices.front();
  default: return formatParamValue(spec, ParamValue::scalar(max ? spec.max : spec.min));
  }
}

std::string testName(std::string n) {
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
}

// Renders the frame (color and the stage's AOV) and checks it as the header says.
void expectSoundFrame(const TestFrame& f, const std::string& technique) {
  ASSERT_TRUE(PassTimer::workCountingSupported())
      << "GL_ARB_pipeline_statistics_query is missing: the passes' work cannot be counted";
  const auto& entry = TechniqueRegistry::instance().get(technique);
  const std::string stageAov = findStage(entry.info.stage)->output;
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::string> aovs = {"color"};
  if (stageAov != "color") aovs.push_back(stageAov);
  TestRender r = renderTestFrame(f, aovs);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.glErrors, 0);
  EXPECT_LE(r.stats.resourceBytes(), kMaxResourceBytes) << [&] {
    std::string list;
    for (const auto& res : r.stats.resources()) list += " " + res.name + " " + std::to_string(res.bytes >> 20) + " MiB;";
    return list;
  }();
  EXPECT_LE(seconds, kMaxSeconds);
  for (const auto& aov : aovs) {
    const Image img = r.renderer->readAov(aov);
    std::size_t bad = 0;
    for (float v : img.pixels) bad += std::isfinite(v) ? 0 : 1;
    EXPECT_EQ(bad, 0u) << aov << " has non-finite values";
  }
  // The frame graph's record of the frame (Renderer::lastPasses: every pass added, kept or culled)
  // against the timer's record of what ran (FrameStats::passes: one entry per executed pass, with
  // the GL work it did).
  std::map<std::string, std::optional<std::uint64_t>> ran;
  for (const auto& p : r.stats.passes()) ran[p.name] = p.workMin;
  int kept = 0;
  for (const auto& p : r.renderer->lastPasses()) {
    if (p.technique != technique || !p.kept) continue;
    ++kept;
    const auto it = ran.find(p.name);
    if (it == ran.end()) {
      ADD_FAILURE() << "pass " << p.name << " was kept but did not run";
      continue;
    }
    ASSERT_TRUE(it->second.has_value()) << "pass " << p.name << ": work not counted";
    EXPECT_GT(*it->second, 0u) << "pass " << p.name << " ran without drawing or dispatching";
  }
  EXPECT_GT(kept, 0) << technique << " added no pass that the frame keeps";
}

// --- Extremes: one parameter at a time --------------------------------------------------------

struct ExtremeCase {
  std::string technique, key, value;
};

std::vector<ExtremeCase> allCases() {
  std::vector<ExtremeCase> cases;
  for (const auto& entry : TechniqueRegistry::instance().entries()) {
    const std::vector<ParamSpec> specs = knobsOf(entry.info);
    for (const auto& spec : specs) {
      std::vector<std::string> values = {extremeValue(spec, false), extremeValue(spec, true)};
      if (spec.type == ParamType::Enum) values = spec.choices; // every choice, not only the ends
      for (const auto& v : values) cases.push_back({entry.info.id, spec.key, v});
    }
    if (specs.empty()) cases.push_back({entry.info.id, "", ""}); // still render it once
  }
  return cases;
}

void PrintTo(const ExtremeCase& c, std::ostream* os) { *os << c.technique << " " << c.key << "=" << c.value; }

class Extremes : public CountingWork<ExtremeCase> {};

TEST_P(Extremes, RendersFiniteWithoutGlErrors) {
  const ExtremeCase& c = GetParam();
  std::vector<std::string> sets;
  if (!c.key.empty()) sets.push_back(c.key + "=" + c.value);
  const auto& entry = TechniqueRegistry::instance().get(c.technique);
  expectSoundFrame(makeTestFrame(entry.info.showcaseScene, c.technique, sets, kSize, kSize), c.technique);
}

INSTANTIATE_TEST_SUITE_P(Registry, Extremes, ::testing::ValuesIn(allCases()),
                         [](const ::testing::TestParamInfo<ExtremeCase>& info) {
                           return testName(info.param.technique + "_" + info.param.key + "_" + info.param.value);
                         });

// --- CombinedExtremes: every knob at its min at once, at its max at once ----------------------

struct CombinedCase {
  std::string technique;
  bool max = false;
};

std::vector<CombinedCase> combinedCases() {
  std::vector<CombinedCase> cases;
  for (const auto& entry : TechniqueRegistry::instance().entries())
    if (!knobsOf(entry.info).empty())
      for (bool max : {false, true}) cases.push_back({entry.info.id, max});
  return cases;
}

void PrintTo(const CombinedCase& c, std::ostream* os) { *os << c.technique << (c.max ? " max" : " min"); }

class CombinedExtremes : public CountingWork<CombinedCase> {};

// The nearest combinations within the budget: where the product of two work knobs at their max
// costs more than the budget's 60 s on llvmpipe, one of them takes the value named here, and the
// combined max keeps every other key at its max. Each key's own max is still rendered alone
// (Extremes above).
struct Cap {
  const char* technique;
  const char* assignment;
};
constexpr Cap kCombinedMaxCaps[] = {
    // Propagation costs lpv.grid^3 x lpv.iterations: both at their max (64^3 cells, 64 steps)
    // measured 55 s for one frame; at the grid's max the iterations keep their default, 8. That
    // still took 20 s, 15 s of it the injection of lpv.rsm_resolution's max, a 1024^2 VPL map (15 s
    // alone too, in Extremes): the suite's time (docs/testing.md) keeps its default, 256, here.
    {"lpv", "lpv.iterations=8"},
    {"lpv", "lpv.rsm_resolution=256"},
    // rsm.sampling's last choice, all_texels, sums every texel of the map for each pixel: at
    // rsm.resolution 1024 that is 2^20 VPLs per pixel, more than 150 s for 64x64 (stopped); the
    // pattern (rsm.samples 1024 over the 1024^2 map at rsm.r_max 0.5) is the combination kept.
    {"rsm", "rsm.sampling=pattern"},
};

TEST_P(CombinedExtremes, RendersFiniteWithoutGlErrors) {
  // No cross-key constraint of the contract makes either combination invalid: the only pair with
  // an order, sdf_shadow.min_step <= sdf_shadow.max_step, is documented as "never below the min
  // step" (the max step is raised to the min step, techniques/sdf_shadow/README.md), and both ends
  // coincide here (0.005 and 0.5 for both keys).
  const CombinedCase& c = GetParam();
  const auto& entry = TechniqueRegistry::instance().get(c.technique);
  std::vector<std::string> sets;
  for (const auto& spec : knobsOf(entry.info)) sets.push_back(spec.key + "=" + extremeValue(spec, c.max));
  if (c.max)
    for (const Cap& cap : kCombinedMaxCaps)
      if (c.technique == cap.technique) sets.push_back(cap.assignment); // the later assignment wins
  expectSoundFrame(makeTestFrame(entry.info.showcaseScene, c.technique, sets, kSize, kSize), c.technique);
}

INSTANTIATE_TEST_SUITE_P(Registry, CombinedExtremes, ::testing::ValuesIn(combinedCases()),
                         [](const ::testing::TestParamInfo<CombinedCase>& info) {
                           return testName(info.param.technique + (info.param.max ? "_max" : "_min"));
                         });

// --- LightSize: light 0's size at 0 and at its maximum, per light type -------------------------

// Light 0's size is read by the shadow stage only: pcss, vssm and msm through the penumbra
// geometry of techniques/common/shadow (uLightSize: light0.radius, or tan(light0.angle) for a
// directional light) and sdf_shadow's cone (sin(light0.angle) or light0.radius / distance).
// shadow_map and pcf do not read it (hard shadows, a fixed kernel) and run as controls. The other
// stages light with light 0 as a point or a direction (rsm and lpv place their VPLs from it), or
// light with rectangular lights (arealight).
constexpr const char* kLightSizeStage = "shadow";

struct LightCase {
  std::string technique;
  LightType type = LightType::Spot;
  bool max = false;
};

const char* typeName(LightType type) {
  return type == LightType::Directional ? "directional" : type == LightType::Spot ? "spot" : "point";
}

std::vector<LightCase> lightCases() {
  std::vector<LightCase> cases;
  for (const auto& entry : TechniqueRegistry::instance().entries())
    if (entry.info.stage == kLightSizeStage)
      for (LightType type : {LightType::Directional, LightType::Spot, LightType::Point})
        for (bool max : {false, true}) cases.push_back({entry.info.id, type, max});
  return cases;
}

void PrintTo(const LightCase& c, std::ostream* os) {
  *os << c.technique << " " << typeName(c.type) << (c.max ? " max" : " 0");
}

class LightSize : public CountingWork<LightCase> {};

TEST_P(LightSize, RendersFiniteWithoutGlErrors) {
  // Built-in scenes: stacked has a directional light 0, contact a spot light 0; the point light is
  // contact's spot made a point light (a scene of its own name, so that it gets its own renderer).
  // The key's maximum is the scene's (scene_params.cpp: 45 degrees; the scene's radius for
  // light0.radius), read from the declared range.
  const LightCase& c = GetParam();
  const bool directional = c.type == LightType::Directional;
  TestFrame f = makeTestFrame(directional ? "stacked" : "contact", c.technique, {}, kSize, kSize);
  if (c.type == LightType::Point) {
    f.scene.lights[0].type = LightType::Point;
    f.scene.name = "contact_point_light";
  }
  const std::string key = directional ? "light0.angle" : "light0.radius";
  const ParamSpec& spec = f.params.spec(key);
  f.params.set(key, ParamValue::scalar(c.max ? spec.max : spec.min));
  SCOPED_TRACE(key + "=" + formatParamValue(spec, f.params.value(key)));
  if (c.type == LightType::Point && (c.technique == "vssm" || c.technique == "msm")) {
    // The moment map is one 2D map: a point light is refused with a usage error naming the
    // technique (techniques/common/shadow/moment_map.cpp, docs/contract.md exit 2).
    try {
      renderTestFrame(f, {"visibility"});
      FAIL() << "expected a usage error";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ExitCode::Usage);
      EXPECT_NE(std::string(e.what()).find(c.technique), std::string::npos) << e.what();
    }
    return;
  }
  expectSoundFrame(f, c.technique);
}

INSTANTIATE_TEST_SUITE_P(Registry, LightSize, ::testing::ValuesIn(lightCases()),
                         [](const ::testing::TestParamInfo<LightCase>& info) {
                           return testName(info.param.technique + "_" + typeName(info.param.type) +
                                           (info.param.max ? "_max" : "_0"));
                         });

} // namespace
} // namespace rtlab
