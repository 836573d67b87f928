// The reference's building blocks: stratified sample patterns, warps, the light model shared
// with shaders/common/lights.glsl, and the progress line.
#include "reference/light_model.h"
#include "reference/progress.h"
#include "reference/sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace rtlab::reference {
namespace {

// Every cell of the m x n grid and every one of the spp intervals of each axis holds one point.
void expectMultiJittered(int spp, int pair) {
  const PixelSampler sampler(3, 12345, spp, true);
  const int m = gridColumns(spp), n = spp / m;
  std::set<int> cells, xs, ys;
  for (int s = 0; s < spp; ++s) {
    const glm::vec2 u = sampler.get(s, pair);
    ASSERT_GE(u.x, 0.0f);
    ASSERT_LT(u.x, 1.0f);
    ASSERT_GE(u.y, 0.0f);
    ASSERT_LT(u.y, 1.0f);
    cells.insert(int(u.x * m) + m * int(u.y * n));
    xs.insert(int(u.x * spp));
    ys.insert(int(u.y * spp));
  }
  EXPECT_EQ(int(cells.size()), spp) << spp;
  EXPECT_EQ(int(xs.size()), spp) << spp;
  EXPECT_EQ(int(ys.size()), spp) << spp;
}

TEST(ReferenceSampling, PatternsAreStratified) {
  EXPECT_EQ(gridColumns(64), 8);
  EXPECT_EQ(gridColumns(12), 3);
  EXPECT_EQ(gridColumns(13), 1);
  for (int spp : {1, 2, 12, 13, 16, 64, 100, 256})
    for (int pair : {0, 1, 5}) expectMultiJittered(spp, pair);
}

TEST(ReferenceSampling, PatternsDependOnSeedPixelAndPairOnly) {
  const PixelSampler a(1, 7, 16, true), b(1, 7, 16, true), c(2, 7, 16, true), d(1, 8, 16, true);
  EXPECT_EQ(a.get(3, 0), b.get(3, 0));
  EXPECT_NE(a.get(3, 0), c.get(3, 0));
  EXPECT_NE(a.get(3, 0), d.get(3, 0));
  EXPECT_NE(a.get(3, 0), a.get(3, 1));
}

TEST(ReferenceSampling, WarpsLandWhereTheyShould) {
  const PixelSampler sampler(1, 0, 256, true);
  double meanCos = 0.0;
  for (int s = 0; s < 256; ++s) {
    const glm::vec2 u = sampler.get(s, 0);
    const glm::vec2 d = squareToDisk(u);
    EXPECT_LE(glm::length(d), 1.0f + 1e-6f);
    const glm::vec3 w = squareToCosineHemisphere(u);
    EXPECT_NEAR(glm::length(w), 1.0f, 1e-5f);
    EXPECT_GE(w.z, 0.0f);
    meanCos += w.z / 256.0;
    const glm::vec3 c = squareToCone(u, std::cos(0.1f));
    EXPECT_GE(c.z, std::cos(0.1f) - 1e-6f);
  }
  EXPECT_NEAR(meanCos, 2.0 / 3.0, 0.01); // E[cos] under the cos/pi density
  const Frame f(glm::normalize(glm::vec3(0.3f, -0.8f, 0.2f)));
  EXPECT_NEAR(glm::dot(f.t, f.b), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::dot(f.t, f.n), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(f.toWorld({0, 0, 1}) - f.n), 0.0f, 1e-6f);
}

TEST(ReferenceLights, IrradianceFollowsLightsGlsl) {
  Light spot;
  spot.type = LightType::Spot;
  spot.position = {0, 4, 0};
  spot.direction = {0, -1, 0};
  spot.intensity = 80.0f;
  spot.color = {1, 0.5f, 0.25f};
  spot.innerConeAngle = 0.5f;
  spot.outerConeAngle = 1.0f;
  glm::vec3 l;
  glm::vec3 e = lightIrradiance(spot, {0, 0, 0}, l);
  EXPECT_NEAR(e.x, 5.0f, 1e-5f); // 80 cd / 4^2
  EXPECT_NEAR(e.y, 2.5f, 1e-5f);
  EXPECT_NEAR(glm::length(l - glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
  EXPECT_EQ(lightIrradiance(spot, {0, 8, 0}, l).x, 0.0f); // behind the spot: outside the cone
  spot.range = 8.0f;                                       // r = 0.5: window (1 - r^4)^2
  EXPECT_NEAR(lightIrradiance(spot, {0, 0, 0}, l).x, 5.0f * std::pow(1.0f - 0.0625f, 2.0f), 1e-5f);
  Light rect;
  rect.type = LightType::Rect;
  rect.position = {0, 2, 0};
  rect.direction = {0, -1, 0};
  rect.width = 2.0f;
  rect.height = 0.5f;
  rect.intensity = 10.0f;
  EXPECT_NEAR(lightIrradiance(rect, {0, 0, 0}, l).x, 10.0f * 1.0f / 4.0f, 1e-5f); // L * area * cos / d^2
  EXPECT_EQ(lightIrradiance(rect, {0, 3, 0}, l).x, 0.0f);                         // behind it
  rect.twoSided = true;                                                           // light<N>.two_sided
  EXPECT_NEAR(lightIrradiance(rect, {0, 3, 0}, l).x, 10.0f * 1.0f / 1.0f, 1e-5f); // the back face: |cos| = 1, d = 1
  EXPECT_NEAR(lightIrradiance(rect, {0, 0, 0}, l).x, 10.0f * 1.0f / 4.0f, 1e-5f); // the front face unchanged
}

TEST(ReferenceLights, ShadowRaysReachTheLightShape) {
  const PixelSampler sampler(1, 0, 64, true);
  Light disk;
  disk.type = LightType::Point;
  disk.position = {0, 3, 0};
  disk.radius = 0.5f;
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = {0, -1, 0};
  sun.angle = 10.0f;
  for (int s = 0; s < 64; ++s) {
    const ShadowRay r = shadowRayToLight(disk, {0, 0, 0}, sampler.get(s, 0));
    const glm::vec3 end = r.direction * (r.tfar / (1.0f - 1e-4f));
    EXPECT_NEAR(end.y, 3.0f, 1e-4f); // the disk faces the point: it lies in the plane y = 3
    EXPECT_LE(std::hypot(end.x, end.z), 0.5f + 1e-4f);
    const ShadowRay d = shadowRayToLight(sun, {0, 0, 0}, sampler.get(s, 0));
    EXPECT_TRUE(std::isinf(d.tfar));
    EXPECT_GE(d.direction.y, std::cos(glm::radians(10.0f)) - 1e-6f);
  }
}

TEST(ReferenceProgress, LineFormat) {
  EXPECT_EQ(ProgressBar::format("reference ao", 0.45, 1.23, true),
            "reference ao [#############                 ]  45% 1.2 s left");
  EXPECT_EQ(ProgressBar::format("reference ao", 0.0, 0.0, false), "reference ao [                              ]   0%");
}

} // namespace
} // namespace rtlab::reference
