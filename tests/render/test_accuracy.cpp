// Accuracy against the ray-traced reference (framework/reference/), same frame and same surface
// points: shadow_map converges with resolution; soft techniques beat the hard shadow under an
// area light; VSSM (without its bleeding reduction) leaks more light into umbrae than MSM where
// occluders stack. Each bound below
// was measured on llvmpipe at 128x128 with a 256-spp reference (values in the comments) and set
// with a margin that still fails if the technique breaks (a missing shadow gives rmse > 0.3).
#include "render_fixture.h"
#include "umbra_leak.h"

#include "app/frame_options.h"
#include "app/reference_run.h"
#include "image/metrics.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace rtlab {
namespace {

constexpr int kSize = 128;
constexpr int kSpp = 256;

struct Measured {
  Image visibility, reference;
  Metrics metrics;
};

Measured measure(const std::string& scene, const std::string& technique, const std::vector<std::string>& sets) {
  TestFrame f = makeTestFrame(scene, technique, sets, kSize, kSize);
  TestRender r = renderTestFrame(f, {"visibility"});
  Measured m;
  m.visibility = r.renderer->readAov("visibility");
  const ResolvedFrame resolved = resolvedOf(f);
  m.reference = renderReferenceFrame(*r.renderer, resolved, "visibility", kSpp, false);
  m.metrics = computeMetrics(m.reference, m.visibility);
  std::printf("%-10s %-8s %-40s rmse %.4f\n", technique.c_str(), scene.c_str(),
              sets.empty() ? "" : sets.front().c_str(), m.metrics.rmse);
  return m;
}

// Mean visibility (light leaked) where the reference is fully shadowed (umbra_leak.h).
double umbraLeak(const Measured& m) { return meanUmbraVisibility(m.reference, m.visibility); }

TEST(Accuracy, ShadowMapMatchesAPointLightAndImprovesWithResolution) {
  // Measured: rmse 0.014 at 2048^2 and 0.074 at 256^2; the residual is edge aliasing (one
  // map texel covers several pixels), the bound 0.15 fails for a missing or misplaced shadow.
  const Measured high = measure("contact", "shadow_map", {"light0.radius=0", "shadow.resolution=2048"});
  const Measured low = measure("contact", "shadow_map", {"light0.radius=0", "shadow.resolution=256"});
  EXPECT_GT(high.metrics.validPixels, std::size_t(kSize * kSize / 2));
  EXPECT_LT(high.metrics.rmse, 0.15);
  EXPECT_LT(high.metrics.rmse, low.metrics.rmse);
}

TEST(Accuracy, SoftTechniquesBeatTheHardShadowUnderAnAreaLight) {
  // Measured rmse: shadow_map 0.037, pcss 0.018, vssm 0.018, msm 0.017 (msm 0.023 before issue
  // 12's exact summed-area table).
  const std::vector<std::string> soft = {"light0.radius=0.3"};
  const double hard = measure("contact", "shadow_map", soft).metrics.rmse;
  for (const char* technique : {"pcss", "vssm", "msm"})
    EXPECT_LT(measure("contact", technique, soft).metrics.rmse, 0.85 * hard) << technique;
}

TEST(Accuracy, PcfSoftensTheHardShadowButNotAsWellAsPcss) {
  // PCF's fixed-width filter (pcf.radius texels) softens every edge alike: closer to the area
  // light's penumbrae than the hard shadow map, but not as close as PCSS, whose width follows the
  // blocker distance. Measured rmse on contact with light0.radius 0.3 at 128x128 (256 spp):
  // shadow_map 0.037, pcf 0.030, pcss 0.018; and with a point light, where
  // the truth is hard, pcf's blur is the error (0.025 against shadow_map's
  // 0.014).
  const std::vector<std::string> soft = {"light0.radius=0.3"};
  const double hard = measure("contact", "shadow_map", soft).metrics.rmse;
  const double pcf = measure("contact", "pcf", soft).metrics.rmse;
  const double pcss = measure("contact", "pcss", soft).metrics.rmse;
  EXPECT_LT(pcf, 0.9 * hard);
  EXPECT_LT(pcss, pcf);
  EXPECT_LT(pcf, 0.04) << "a missing or misplaced shadow gives more than 0.3";
  const std::vector<std::string> point = {"light0.radius=0", "shadow.resolution=2048"};
  const double hardPoint = measure("contact", "shadow_map", point).metrics.rmse;
  const double pcfPoint = measure("contact", "pcf", point).metrics.rmse;
  EXPECT_GT(pcfPoint, hardPoint) << "under a point light the filter's blur is error";
}

TEST(Accuracy, VssmLeaksMoreLightIntoUmbraeThanMsm) {
  // The raw bounds: both without their light-bleeding reduction (VSSM's default cuts the lowest
  // 20% of the bound and so hides most leaking at the cost of harder edges; MSM's at equal
  // reduction: tests/render/test_msm.cpp). Measured umbra leak: vssm
  // 0.014 unreduced, msm 0.0077 (before issue 12's exact summed-area table, whose rounding added
  // speckles to both: vssm 0.032, msm 0.0245).
  const double vssm = umbraLeak(measure("stacked", "vssm", {"light0.angle=2", "vssm.bleed_reduction=0"}));
  const double msm = umbraLeak(measure("stacked", "msm", {"light0.angle=2", "msm.bleed_reduction=0"}));
  std::printf("umbra leak on stacked: vssm %.4f, msm %.4f\n", vssm, msm);
  EXPECT_GT(vssm, 0.01) << "VSSM's bleeding should be measurable";
  EXPECT_LT(msm, vssm);
}

} // namespace
} // namespace rtlab
