// MSM's light-bleeding reduction and four-moment blocker search (issue 19; techniques/msm/README.md,
// "Light-bleeding reduction" and "Four-moment blocker search"):
// - msm.bleed_reduction only remaps the final visibility, v_a = clamp((v_0 - a) / (1 - a), 0, 1)
//   (to the half-float rounding of the visibility target), so 0 is the raw 4MSM bound and the
//   blocker search does not change;
// - a larger reduction leaks monotonically less into the umbra under stacked occluders, and at
//   every equal reduction MSM leaks less than VSSM there (the umbra leak of umbra_leak.h);
// - the four-moment blocker search, evaluated on given moment vectors: it recovers the mean depth
//   of two blocker layers exactly where the two-moment estimate cannot, and stays finite, in
//   [0, t], and right about "no blocker" at the extremes (one depth in the box, t at 0 and 1,
//   the moment bias at its limits);
// - its visibility error against the reference is within the bound measured below.
// Frames are 320x180 with a 64-spp reference: a pixel whose light is blocked over the whole disk
// or cone reads exactly 0 at any sample count, so the umbra is exact.
#include "frame_graph_fixture.h"
#include "render_fixture.h"
#include "umbra_leak.h"

#include "app/reference_run.h"
#include "gl/buffer.h"
#include "image/metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace rtlab {
namespace {

constexpr int kMsmWidth = 320, kMsmHeight = 180;
constexpr int kMsmSpp = 64;
// The frames of docs/performance.md's shadow family: a directional light of angular radius 2° on
// stacked (two plates over the ground: both plates' depths in the filter boxes under the lower
// one), a spot light of radius 0.3 on contact.
const std::vector<std::string> kStackedLight = {"light0.angle=2"};
const std::vector<std::string> kContactLight = {"light0.radius=0.3"};

std::vector<std::string> withSets(std::vector<std::string> sets, const std::vector<std::string>& more) {
  sets.insert(sets.end(), more.begin(), more.end());
  return sets;
}

Image msmTestAov(const std::string& scene, const std::string& technique, const std::vector<std::string>& sets,
                 const std::string& aov = "visibility") {
  TestFrame f = makeTestFrame(scene, technique, sets, kMsmWidth, kMsmHeight);
  TestRender r = renderTestFrame(f, {aov});
  EXPECT_EQ(r.glErrors, 0) << technique;
  return r.renderer->readAov(aov);
}

// The visibility reference of a scene and light (it does not depend on the technique), once.
const Image& msmTestReference(const std::string& scene, const std::vector<std::string>& light) {
  static std::map<std::string, Image> cache;
  const std::string key = scene + (light.empty() ? "" : " " + light.front());
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  TestFrame f = makeTestFrame(scene, "msm", light, kMsmWidth, kMsmHeight);
  TestRender r = renderTestFrame(f, {"visibility"});
  return cache[key] = renderReferenceFrame(*r.renderer, resolvedOf(f), "visibility", kMsmSpp, false);
}

double leakOf(const std::string& technique, double reduction) {
  char set[64];
  std::snprintf(set, sizeof set, "%s.bleed_reduction=%g", technique.c_str(), reduction);
  const Image v = msmTestAov("stacked", technique, withSets(kStackedLight, {set}));
  return meanUmbraVisibility(msmTestReference("stacked", kStackedLight), v);
}

TEST(MsmBleedReduction, RemapsTheRawBoundAndLeavesTheSearchAlone) {
  const Image raw = msmTestAov("stacked", "msm", withSets(kStackedLight, {"msm.bleed_reduction=0"}));
  const Image rawBlocker =
      msmTestAov("stacked", "msm", withSets(kStackedLight, {"msm.bleed_reduction=0"}), "msm.blocker_depth");
  std::size_t partial = 0;
  for (float v : raw.pixels) partial += v > 0.02f && v < 0.98f ? 1 : 0;
  EXPECT_GT(partial, std::size_t(500)) << "the frame should hold penumbrae for the remap to act on";
  for (float a : {0.1f, 0.5f, 0.95f}) {
    const std::string set = "msm.bleed_reduction=" + std::to_string(a);
    const Image reduced = msmTestAov("stacked", "msm", withSets(kStackedLight, {set}));
    // The visibility target is R16F (techniques/common/shadow/shadow_pass.cpp): both images are
    // rounded to half floats (llvmpipe truncates: an error up to one step, at most 2^-10 of the
    // value), the reduced one after the remap, which stretches the raw image's rounding by
    // 1 / (1 - a).
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < raw.pixels.size(); ++i) {
      const float expected = std::clamp((raw.pixels[i] - a) / (1.0f - a), 0.0f, 1.0f);
      const float bound = 0x1p-10f * (raw.pixels[i] / (1.0f - a) + expected) + 1e-6f;
      wrong += std::abs(reduced.pixels[i] - expected) > bound ? 1 : 0;
    }
    EXPECT_EQ(wrong, 0u) << set;
    const Image blocker = msmTestAov("stacked", "msm", withSets(kStackedLight, {set}), "msm.blocker_depth");
    EXPECT_EQ(blocker.pixels, rawBlocker.pixels) << set;
  }
}

TEST(MsmBleedReduction, MoreReductionLeaksLessAndMsmLessThanVssmAtEqualReduction) {
  // Measured on llvmpipe at 320x180 (mean visibility over the reference's umbra), reductions 0,
  // 0.1, 0.2, 0.3: msm 0.0072, 0.0017, 0.00074, 0.00028; vssm 0.0130, 0.0049, 0.0012, 0.00040.
  const std::vector<double> reductions = {0.0, 0.1, 0.2, 0.3};
  std::vector<double> msm, vssm;
  for (double a : reductions) {
    msm.push_back(leakOf("msm", a));
    vssm.push_back(leakOf("vssm", a));
    std::printf("umbra leak on stacked at reduction %.2f: msm %.5f, vssm %.5f\n", a, msm.back(), vssm.back());
  }
  EXPECT_GT(msm.front(), 0.002) << "MSM's raw bound should leak measurably under the plates";
  for (std::size_t k = 0; k < reductions.size(); ++k) {
    if (k > 0) {
      EXPECT_LE(msm[k], msm[k - 1]) << reductions[k];
      if (msm[k - 1] > 0.0) {
        EXPECT_LT(msm[k], msm[k - 1]) << reductions[k];
      }
    }
    if (vssm[k] > 0.0) {
      EXPECT_LT(msm[k], vssm[k]) << "reduction " << reductions[k];
    } else {
      EXPECT_EQ(msm[k], 0.0) << "reduction " << reductions[k];
    }
  }
}

// ---- the four-moment blocker search on given moments (tests/render/shaders/moment_blocker.comp) ----

struct BlockerCase {
  glm::dvec4 moments;
  double t;
};
struct BlockerResult {
  bool found4;
  float z4;
  bool found2;
  float z2;
};

// Moments (z, z^2, z^3, z^4) of a discrete depth distribution {(depth, weight)}, in doubles.
glm::dvec4 momentsOf(const std::vector<std::pair<double, double>>& distribution) {
  glm::dvec4 m(0.0);
  for (const auto& [z, w] : distribution) m += w * glm::dvec4(z, z * z, z * z * z, z * z * z * z);
  return m;
}

std::vector<BlockerResult> evaluateBlockerSearch(const std::vector<BlockerCase>& cases, float momentBias) {
  testContext().makeCurrent();
  GraphHarness h(1, 1);
  std::vector<glm::vec4> input;
  for (const auto& c : cases) {
    input.push_back(glm::vec4(c.moments));
    input.push_back(glm::vec4(float(c.t), 0.0f, 0.0f, 0.0f));
  }
  gl::BufferObject in({gl::BufferKind::Storage, input.size() * sizeof(glm::vec4)}, "moment_blocker.cases");
  in.upload(input.data(), input.size() * sizeof(glm::vec4));
  gl::BufferObject out({gl::BufferKind::Storage, cases.size() * sizeof(glm::vec4)}, "moment_blocker.results");
  gl::Program& p = h.program({testShader("moment_blocker.comp")});
  p.set("uMomentBias", momentBias);
  p.use();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
  glDispatchCompute(GLuint(cases.size()), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const std::vector<glm::vec4> raw = out.downloadAs<glm::vec4>();
  // Back to the state the frame graph expects (no program, no storage buffers bound).
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
  glUseProgram(0);
  std::vector<BlockerResult> results;
  for (const glm::vec4& r : raw) results.push_back({r.x > 0.5f, r.y, r.z > 0.5f, r.w});
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  return results;
}

TEST(MsmBlockerSearch, FourMomentsRecoverTheMeanDepthOfTwoBlockerLayers) {
  // Blockers at two depths and the receiver's own depth t in the box: three support points, so
  // the three-point distribution on {t, z2, z3} is the box's distribution itself (up to the moment
  // bias) and its blockers' mean is exact. The two-moment estimate assumes one blocker depth.
  struct Layered {
    std::vector<std::pair<double, double>> distribution;
    double t;
  };
  const std::vector<Layered> layered = {
      {{{0.2, 0.3}, {0.5, 0.3}, {0.8, 0.4}}, 0.8},  // blockers' mean 0.35
      {{{0.1, 0.25}, {0.6, 0.25}, {0.9, 0.5}}, 0.9}, // 0.35
      {{{0.3, 0.5}, {0.6, 0.5}}, 0.9},               // fully blocked: 0.45
      {{{0.45, 0.2}, {0.55, 0.2}, {0.7, 0.6}}, 0.7}, // close layers: 0.5
  };
  std::vector<BlockerCase> cases;
  for (const auto& l : layered) cases.push_back({momentsOf(l.distribution), l.t});
  const std::vector<BlockerResult> r = evaluateBlockerSearch(cases, 3e-5f);
  for (std::size_t i = 0; i < layered.size(); ++i) {
    double mass = 0, first = 0;
    for (const auto& [z, w] : layered[i].distribution)
      if (z < layered[i].t) {
        mass += w;
        first += w * z;
      }
    const double truth = first / mass;
    std::printf("two blocker layers, t %.2f: truth %.4f, four moments %.4f, two moments %.4f\n", layered[i].t, truth,
                r[i].z4, r[i].z2);
    EXPECT_TRUE(r[i].found4) << i;
    // Measured: within 6e-4 (fp32 and the moment bias); the two-moment estimate is 0.012-0.11 off.
    EXPECT_NEAR(r[i].z4, truth, 2e-3) << i;
    EXPECT_GT(std::abs(r[i].z2 - truth), 10.0 * std::abs(r[i].z4 - truth)) << i;
  }
}

TEST(MsmBlockerSearch, FiniteAndInRangeAtTheExtremes) {
  // One depth z in the box (a flat receiver or a blocker's interior), t at 0, at 1, at z and next
  // to it, at the smallest, the default and the largest moment bias.
  for (float bias : {1e-7f, 3e-5f, 0.1f}) {
    std::vector<BlockerCase> cases;
    for (double z : {0.0, 0.25, 0.5, 0.75, 1.0})
      for (double t : {0.0, 1.0, z, z - 0.02, z + 0.02, z + 0.3})
        if (t >= 0.0 && t <= 1.0) cases.push_back({momentsOf({{z, 1.0}}), t});
    const std::vector<BlockerResult> r = evaluateBlockerSearch(cases, bias);
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const double z = cases[i].moments.x, t = cases[i].t;
      const std::string what = "bias " + std::to_string(bias) + ", depth " + std::to_string(z) + ", t " +
                               std::to_string(t);
      ASSERT_TRUE(std::isfinite(r[i].z4)) << what;
      EXPECT_GE(r[i].z4, 0.0f) << what;
      EXPECT_LE(r[i].z4, float(t)) << what;
      // At or behind the receiver nothing blocks, and a clear blocker is found at its depth, unless
      // the largest bias moves a tenth of the mass to depths 0 and 1 (then half of it blocks).
      if (z >= t && bias < 1e-3f) {
        EXPECT_FALSE(r[i].found4) << what;
      }
      if (z + 0.25 < t) {
        EXPECT_TRUE(r[i].found4) << what;
        if (bias < 1e-3f) {
          EXPECT_NEAR(r[i].z4, z, 0.01) << what;
        }
      }
    }
  }
}

TEST(MsmBlockerSearch, FourMomentErrorAgainstTheReferenceWithinMeasuredBound) {
  // Measured on llvmpipe at 320x180 against the 64-spp reference, default reduction (0.1):
  // stacked two_moment 0.0111, four_moment 0.0084; contact 0.0126 and 0.0119. The bound 0.015
  // is 1.25 times the larger; a search that never finds a blocker (no shadow) gives about 0.3.
  for (const auto& [scene, light] : {std::pair{"stacked", kStackedLight}, std::pair{"contact", kContactLight}}) {
    const Image& reference = msmTestReference(scene, light);
    const double two =
        computeMetrics(reference, msmTestAov(scene, "msm", withSets(light, {"msm.blocker_search=two_moment"}))).rmse;
    const Image four = msmTestAov(scene, "msm", withSets(light, {"msm.blocker_search=four_moment"}));
    std::size_t nonFinite = 0;
    for (float v : four.pixels) nonFinite += std::isfinite(v) ? 0 : 1;
    EXPECT_EQ(nonFinite, 0u) << scene;
    const double fourRmse = computeMetrics(reference, four).rmse;
    std::printf("msm on %s: visibility rmse two_moment %.5f, four_moment %.5f\n", scene, two, fourRmse);
    EXPECT_LT(fourRmse, 0.015) << scene;
    EXPECT_LT(fourRmse, two) << scene;
  }
}

} // namespace
} // namespace rtlab
