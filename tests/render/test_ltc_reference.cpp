// ltc against the arealight reference (docs/contract.md "Area lights"; rtlab reference --aov
// arealight): the whole AOV, per roughness, on `arealight_ramp` (strips of perceptual roughness
// 0.1 .. 0.9 in view, a dielectric and a metal, grazing views, a light straddling the horizon) and
// on `arealight` with its floor as a mirror, at 0.5 and fully rough. ltc's error is bias (the fit,
// assets/ltc/README.md, and the diffuse (1 - F) factor, techniques/ltc/README.md), so each bound is
// the measured relative RMSE with a margin, not a sampling tolerance.
#include "arealight_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace rtlab {
namespace {

// Relative RMSE (rmse / mean radiance) of ltc per roughness strip of arealight_ramp at 96x54
// against a 2048-spp reference (whose own noise is below area_mc's error at 256 samples against it,
// 0.4 to 3.8 % per strip, AreaMc.ErrorPerRoughnessOnTheRamp: a small part of ltc's). Measured (llvmpipe), strips
// 0.1 .. 0.9: 2.5, 3.1, 11.9, 26.0, 31.4, 34.3, 22.1, 11.7, 7.9 %. The error is concentrated at the
// foot of the light standing in the floor, on the far (copper) half: points there see a light that
// fills their lobe at grazing angles (cos theta_v below 0.1), where the fit is worst (L1 error 0.3
// to 0.7 at roughness 0.3 to 0.7, assets/ltc/README.md) — the central strips are the ones under
// that light. Each bound is the measurement plus 30 %: a regression bound, since the error is the
// fit's bias and does not shrink with samples.
TEST(LtcReference, ErrorPerRoughnessOnTheRamp) {
  const TestFrame f = makeTestFrame("arealight_ramp", "ltc", {}, 96, 54);
  const Image ref = test::arealightReference(f, 2048);
  const Image got = test::arealightAov(f);
  const std::vector<test::RoughnessBin> bins = test::errorPerRoughness(f, got, ref);
  constexpr int kBins = 11;
  ASSERT_EQ(int(bins.size()), kBins);
  int measured = 0;
  for (int b = 0; b < kBins; ++b) {
    if (bins[b].values < 150.0) continue; // too few pixels of that strip in view
    const double relative = bins[b].relative;
    std::printf("ltc on the ramp, roughness %.1f: %5.0f values, relative rmse %.3f%%\n", b / 10.0, bins[b].values,
                100.0 * relative);
    constexpr double kMeasured[kBins] = {0.0, 0.025, 0.031, 0.119, 0.260, 0.314, 0.343, 0.221, 0.117, 0.079, 0.0};
    const double bound = 1.3 * kMeasured[b];
    EXPECT_LT(relative, bound) << "roughness " << b / 10.0;
    ++measured;
  }
  EXPECT_GE(measured, 7);
}

// The `arealight` floor at roughness 0 (alpha at its clamp), 0.5 and 1: relative RMSE against a
// 1024-spp reference over the whole frame (floor, sphere 0.5, box 0.35). Measured: 3.7 % (bias
// -0.2 %), 13.0 % (bias +3.8 %: the low camera sees the floor at cos theta_v 0.15 to 0.5, where the
// fit's error at roughness 0.5 is about 0.35 on average) and 1.9 %; bounds the measurement plus 30 %.
TEST(LtcReference, ErrorPerFloorRoughness) {
  struct Case {
    float roughness;
    double bound;
  };
  for (const Case c : {Case{0.0f, 0.049}, Case{0.5f, 0.17}, Case{1.0f, 0.025}}) {
    const TestFrame f = test::withFloorRoughness(makeTestFrame("arealight", "ltc", {}, 64, 36), c.roughness,
                                                 "arealight_ltc_r" + std::to_string(int(c.roughness * 100)));
    const test::ArealightError e = test::arealightError(test::arealightAov(f), test::arealightReference(f, 1024));
    std::printf("ltc on arealight, floor roughness %.2f: relative rmse %.3f%%, bias %.3f%%\n", c.roughness,
                100.0 * e.relative(), 100.0 * e.bias / e.mean);
    EXPECT_LT(e.relative(), c.bound) << c.roughness;
  }
}

} // namespace
} // namespace rtlab
