// The arealight reference's estimator (techniques/area_mc/area_mc_model.h, docs/contract.md "Area
// lights"): it matches an independent quadrature of the same integral over the rectangle's area, its
// noise falls like 1/sqrt(spp), and the cases with a known answer hold (below the horizon 0, a
// one-sided light seen from behind 0, two-sided = mirrored, far away = the point light).
#include "reference/light_model.h"
#include "rect_quadrature.h"
#include "techniques/area_mc/area_mc_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace rtlab {
namespace {

using area_mc::RectLight;
using area_mc::ShadingPoint;

// The `arealight` scene's light: 2 x 1 at height 2.5, facing down, 10 nits.
RectLight sceneLight() {
  RectLight l;
  l.center = {0.0, 2.5, -1.0};
  l.normal = {0.0, -1.0, 0.0};
  l.right = {1.0, 0.0, 0.0};
  l.up = {0.0, 0.0, -1.0};
  l.width = 2.0;
  l.height = 1.0;
  l.radiance = glm::dvec3(10.0);
  return l;
}

ShadingPoint floorPoint(glm::dvec3 p, glm::dvec3 eye, double roughness, double metallic = 0.0) {
  ShadingPoint x;
  x.position = p;
  x.normal = {0.0, 1.0, 0.0};
  x.toViewer = glm::normalize(eye - p);
  x.material = {glm::dvec3(0.5, 0.4, 0.3), metallic, roughness};
  return x;
}

// The integral by the midpoint rule on a k x k grid over the rectangle (tests/render/rect_quadrature.h).
glm::dvec3 quadrature(const ShadingPoint& x, const RectLight& light, int k) {
  return test::rectQuadrature(light, x.position, x.normal, x.toViewer, x.material, k, k);
}

glm::dvec3 estimate(const ShadingPoint& x, const RectLight& light, int spp, unsigned seed, bool stratified = true,
                    area_mc::Strategy strategy = area_mc::Strategy::Mis) {
  const reference::PixelSampler sampler(seed, 7, spp, stratified);
  return area_mc::estimateRect(x, light, sampler, 0, strategy);
}

double luminance(const glm::dvec3& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

// Points on the floor under and beside the light, seen from the scene's camera, for a glossy, a
// medium and a rough dielectric and a glossy metal: the reference at 65536 spp agrees with a
// 1536^2-point quadrature within 0.1% (measured: at most 0.001%, README "The reference").
TEST(ArealightReference, MatchesAnIndependentQuadrature) {
  const RectLight light = sceneLight();
  const glm::dvec3 eye(0.0, 1.6, 7.0);
  struct Case {
    glm::dvec3 p;
    double roughness, metallic;
  };
  const std::vector<Case> cases = {{{0.0, 0.0, 0.0}, 0.2, 0.0},   {{0.3, 0.0, 1.5}, 0.2, 0.0},
                                   {{-1.5, 0.0, 0.5}, 0.5, 0.0},  {{1.0, 0.0, -2.5}, 1.0, 0.0},
                                   {{0.2, 0.0, 1.0}, 0.15, 1.0},  {{2.5, 0.0, 2.0}, 0.35, 0.0}};
  double worst = 0.0;
  for (const Case& c : cases) {
    const ShadingPoint x = floorPoint(c.p, eye, c.roughness, c.metallic);
    const glm::dvec3 exact = quadrature(x, light, 1536);
    const glm::dvec3 mc = estimate(x, light, 65536, 3);
    for (int k = 0; k < 3; ++k) {
      ASSERT_GT(exact[k], 0.0);
      worst = std::max(worst, std::abs(mc[k] / exact[k] - 1.0));
      EXPECT_NEAR(mc[k] / exact[k], 1.0, 1e-3) << "point " << c.p.x << "," << c.p.z << " roughness " << c.roughness
                                               << " metallic " << c.metallic << " channel " << k;
    }
  }
  std::printf("arealight reference vs quadrature: largest relative difference %.5f\n", worst);
}

// Plain Monte Carlo (independent samples): the standard deviation over seeds falls by 4 from 16 to
// 256 spp (1/sqrt(spp)); the stratified pattern falls at least as fast.
TEST(ArealightReference, NoiseFallsLikeOneOverSqrtSpp) {
  const RectLight light = sceneLight();
  const ShadingPoint x = floorPoint({0.4, 0.0, 0.8}, {0.0, 1.6, 7.0}, 0.3);
  auto deviation = [&](int spp, bool stratified) {
    constexpr int kSeeds = 200;
    double sum = 0.0, sum2 = 0.0;
    for (unsigned s = 0; s < kSeeds; ++s) {
      const double v = luminance(estimate(x, light, spp, 100 + s, stratified));
      sum += v;
      sum2 += v * v;
    }
    const double mean = sum / kSeeds;
    return std::sqrt(std::max(0.0, sum2 / kSeeds - mean * mean));
  };
  const double plain16 = deviation(16, false), plain256 = deviation(256, false);
  const double strat16 = deviation(16, true), strat256 = deviation(256, true);
  std::printf("deviation 16 -> 256 spp: plain %.3f -> %.3f (x%.2f), stratified %.3f -> %.3f (x%.2f)\n", plain16,
              plain256, plain16 / plain256, strat16, strat256, strat16 / strat256);
  EXPECT_NEAR(plain16 / plain256, 4.0, 0.8);
  EXPECT_LT(strat16, plain16);
  EXPECT_GT(strat16 / strat256, 3.5);
}

// A light wholly below the point's tangent plane adds exactly 0, whichever way it faces; a one-sided
// light seen from behind adds exactly 0, lit or not from the front.
TEST(ArealightReference, BelowTheHorizonAndBehindAOneSidedLightIsZero) {
  const ShadingPoint x = floorPoint({0.0, 0.0, 0.0}, {0.0, 1.6, 7.0}, 0.3);
  for (bool twoSided : {false, true}) {
    for (double facing : {-1.0, 1.0}) {
      RectLight below = sceneLight();
      below.center.y = -0.6; // the whole rectangle under y = 0
      below.normal = {0.0, facing, 0.0};
      below.twoSided = twoSided;
      for (auto strategy : {area_mc::Strategy::Mis, area_mc::Strategy::Light, area_mc::Strategy::Brdf})
        EXPECT_EQ(estimate(x, below, 256, 1, true, strategy), glm::dvec3(0.0)) << twoSided << " " << facing;
    }
  }
  RectLight back = sceneLight();
  back.normal = {0.0, 1.0, 0.0}; // emits upward, away from the floor
  for (auto strategy : {area_mc::Strategy::Mis, area_mc::Strategy::Light, area_mc::Strategy::Brdf})
    EXPECT_EQ(estimate(x, back, 256, 1, true, strategy), glm::dvec3(0.0));
  EXPECT_GT(luminance(estimate(x, sceneLight(), 256, 1)), 0.1);
}

// A light straddling the horizon (arealight_ramp's: 1.2 x 1 from y = -0.3 to 0.7, facing +z) is
// clipped: at floor points in front of it the estimate equals the quadrature of its part above the
// floor alone (1.2 x 0.7), within 0.1%: nothing leaks from below the tangent plane. The points stay
// 1 or more from the light: at 0.3 from it, with roughness 0.1 and this grazing view, the glossy
// lobe's footprint spans a few cells of a 1536^2 quadrature, which comes out 18% short (a 6144^2
// one agrees with the estimate to 1e-5).
TEST(ArealightReference, AStraddlingLightIsClippedAtTheHorizon) {
  RectLight straddling;
  straddling.center = {0.0, 0.2, -4.5};
  straddling.normal = {0.0, 0.0, 1.0};
  straddling.right = {1.0, 0.0, 0.0};
  straddling.up = {0.0, 1.0, 0.0};
  straddling.width = 1.2;
  straddling.height = 1.0;
  straddling.radiance = glm::dvec3(6.0);
  straddling.twoSided = true;
  RectLight above = straddling;
  above.center.y = 0.35;
  above.height = 0.7;
  for (const glm::dvec3 p : {glm::dvec3(0.3, 0.0, -3.5), glm::dvec3(-0.8, 0.0, -2.0), glm::dvec3(-0.5, 0.0, -3.0)}) {
    for (double roughness : {0.1, 0.5, 1.0}) {
      const ShadingPoint x = floorPoint(p, {0.0, 0.6, 4.5}, roughness);
      const glm::dvec3 exact = quadrature(x, above, 1536);
      const glm::dvec3 mc = estimate(x, straddling, 65536, 9);
      ASSERT_GT(exact.x, 0.0);
      EXPECT_NEAR(mc.x / exact.x, 1.0, 1e-3) << p.z << " " << roughness;
    }
  }
}

// A two-sided light gives from behind what the one-sided light gives from the front: the same
// samples, the same value.
TEST(ArealightReference, TwoSidedIsTheMirroredOneSided) {
  const ShadingPoint x = floorPoint({0.5, 0.0, 0.5}, {0.0, 1.6, 7.0}, 0.25);
  RectLight front = sceneLight(), mirrored = sceneLight();
  mirrored.normal = -front.normal;
  mirrored.twoSided = true;
  const glm::dvec3 a = estimate(x, front, 1024, 5), b = estimate(x, mirrored, 1024, 5);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(b[k], a[k], 1e-12 * a[k]);
  EXPECT_GT(luminance(a), 0.1);
}

// Far away a rectangle is a point light: at 1e4 units (0.01 degrees across) the estimate equals
// lightIrradiance (framework/reference/light_model.h: L_e A cos(theta') / d^2) times the BRDF's
// f cos(theta) within 0.1%, for a tilted light and a surface it lights at 40 degrees.
TEST(ArealightReference, AFarLightIsThePointLight) {
  const glm::dvec3 p(0.0, 0.0, 0.0);
  const glm::dvec3 toLight = glm::normalize(glm::dvec3(std::sin(glm::radians(40.0)), std::cos(glm::radians(40.0)), 0.0));
  Light light;
  light.type = LightType::Rect;
  light.position = glm::vec3(p + 1e4 * toLight);
  light.direction = glm::normalize(glm::vec3(-0.2f, -1.0f, 0.1f));
  light.right = glm::normalize(glm::cross(light.direction, glm::vec3(0, 0, 1)));
  light.up = glm::cross(light.right, light.direction);
  light.width = 2.0f;
  light.height = 1.0f;
  light.color = {1.0f, 0.8f, 0.6f};
  light.intensity = 1e6f;
  for (double roughness : {0.3, 0.8}) {
    const ShadingPoint x = floorPoint(p, {-3.0, 2.0, 1.0}, roughness);
    glm::vec3 l;
    const glm::vec3 e = reference::lightIrradiance(light, glm::vec3(p), l);
    const glm::dvec3 expected = glm::dvec3(e) * brdf::evaluateBrdfCos(x.normal, x.toViewer, glm::dvec3(l), x.material);
    const glm::dvec3 got = estimate(x, area_mc::rectLightFrom(light), 64, 1);
    for (int k = 0; k < 3; ++k) {
      ASSERT_GT(expected[k], 0.0);
      EXPECT_NEAR(got[k] / expected[k], 1.0, 1e-3) << roughness << " " << k;
    }
  }
}

} // namespace
} // namespace rtlab
