// The CPU reference (framework/reference) on synthetic scenes with known answers: unoccluded
// points, a point light behind an occluder, ambient occlusion beside a wall against the closed
// form of docs/measuring.md, the Monte-Carlo convergence rate, one-bounce irradiance from a lit
// plane, determinism across thread counts, and the image contract (mask, channels, errors).
#include "reference/reference.h"
#include "util/error.h"

#include "test_reference_scenes.h"
#include "test_util.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace rtlab {
namespace {

using test::addMaterial;
using test::addQuad;
using test::aoBesideWall;
using test::gridSurfaces;
using test::wallCase;
using test::WallCase;

constexpr float kPi = std::numbers::pi_v<float>;

// A 40x40 floor at y = 0 facing up, seen from above.
Scene floorScene() {
  Scene s;
  s.name = "floor";
  addQuad(s, {0, 0, 0}, {20, 0, 0}, {0, 0, -20});
  s.camera.position = {0, 10, 5};
  return s;
}

// 16x16 points on the floor in [-2, 2]^2.
SurfaceData floorPoints(int n = 16) {
  return gridSurfaces(n, n, {0, 1, 0}, [n](int x, int y) {
    return glm::vec3(-2.0f + 4.0f * (x + 0.5f) / n, 0.0f, -2.0f + 4.0f * (y + 0.5f) / n);
  });
}

ReferenceOptions opts(int spp, float aoRadius = 0.5f) {
  ReferenceOptions o;
  o.spp = spp;
  o.aoRadius = aoRadius;
  return o;
}

float minOf(const Image& im) {
  float m = 1e30f;
  for (float v : im.pixels) m = std::min(m, v);
  return m;
}
float maxOf(const Image& im) {
  float m = -1e30f;
  for (float v : im.pixels) m = std::max(m, v);
  return m;
}

TEST(Reference, UnoccludedPlaneHasVisibilityOneAndAoOne) {
  const SurfaceData points = floorPoints();
  for (const Light& light : {test::directional({0.3f, -1, 0.2f}, 3, 5), test::directional({0, -1, 0}, 3, 0),
                             test::point({0.5f, 3, 0}, 10, 0.5f), test::point({0, 3, 0}, 10, 0),
                             test::rect({0, 3, 0}, 2, 1, 10)}) {
    Scene s = floorScene();
    s.lights = {light};
    const Image v = renderReference(s, points, "visibility", opts(16));
    EXPECT_EQ(minOf(v), 1.0f) << "light type " << int(light.type);
    const Image ao = renderReference(s, points, "ao", opts(16, 2.0f));
    EXPECT_EQ(minOf(ao), 1.0f);
  }
}

TEST(Reference, PointLightBehindOccluderGivesZero) {
  Scene s = floorScene();
  addQuad(s, {0, 1, 0}, {1, 0, 0}, {0, 0, -1}); // a 2x2 occluder 1 above the floor
  s.lights = {test::point({0, 3, 0}, 10, 0)};
  // Points under the occluder's centre, and points far outside its shadow.
  const SurfaceData inside = gridSurfaces(8, 8, {0, 1, 0}, [](int x, int y) {
    return glm::vec3(-0.5f + x / 8.0f, 0.0f, -0.5f + y / 8.0f);
  });
  const SurfaceData outside = gridSurfaces(8, 8, {0, 1, 0}, [](int x, int y) {
    return glm::vec3(5.0f + x / 8.0f, 0.0f, -0.5f + y / 8.0f);
  });
  EXPECT_EQ(maxOf(renderReference(s, inside, "visibility", opts(16))), 0.0f);
  EXPECT_EQ(minOf(renderReference(s, outside, "visibility", opts(16))), 1.0f);
  // A disk light of radius 0.2 at 3: the umbra under the 2x2 occluder's centre is about
  // 2.6 wide, so the inner points stay fully dark whatever the samples.
  s.lights[0].radius = 0.2f;
  EXPECT_EQ(maxOf(renderReference(s, inside, "visibility", opts(64))), 0.0f);
  // A transparent occluder casts nothing (the GPU leaves it out of shadow maps and G-buffer).
  Scene glass = floorScene();
  addQuad(glass, {0, 1, 0}, {1, 0, 0}, {0, 0, -1}, -1, true);
  glass.lights = {test::point({0, 3, 0}, 10, 0)};
  EXPECT_EQ(minOf(renderReference(glass, inside, "visibility", opts(4))), 1.0f);
}

TEST(Reference, AlphaMaskedOccludersAreCutOutAsInTheGBuffer) {
  // A 1x1 texture: alpha 0 cuts the whole occluder out (alpha < cutoff), alpha 1 keeps it.
  for (const std::uint8_t alpha : {std::uint8_t(0), std::uint8_t(255)}) {
    Scene s = floorScene();
    TextureImage t;
    t.width = t.height = 1;
    t.rgba8 = {255, 255, 255, alpha};
    t.srgb = true;
    s.textures.push_back(t);
    Material m;
    m.alphaMode = AlphaMode::Mask;
    m.alphaCutoff = 0.5f;
    m.baseColorTexture = 0;
    s.materials.push_back(m);
    addQuad(s, {0, 1, 0}, {1, 0, 0}, {0, 0, -1}, 0);
    s.lights = {test::point({0, 3, 0}, 10, 0)};
    const Image v = renderReference(s, floorPoints(4), "visibility", opts(1));
    EXPECT_EQ(v.at(1, 1, 0), alpha == 0 ? 1.0f : 0.0f) << int(alpha); // (-0.5, 0, -0.5): under the quad
  }
}

TEST(Reference, LightBelowTheSurfaceIsHidden) {
  Scene s = floorScene();
  s.lights = {test::point({0, -3, 0}, 10, 0)}; // under the open floor quad: only its own surface hides it
  EXPECT_EQ(maxOf(renderReference(s, floorPoints(4), "visibility", opts(4))), 0.0f);
}

TEST(Reference, AoBesideWallMatchesClosedForm) {
  const int columns = 24, rows = 8, spp = 256;
  const WallCase c = wallCase(columns, rows, 1.25f);
  const Image ao = renderReference(c.scene, c.points, "ao", opts(spp, c.radius));
  for (int x = 0; x < columns; ++x) {
    double mean = 0.0;
    for (int y = 0; y < rows; ++y) mean += ao.at(x, y, 0);
    mean /= rows;
    const double expected = c.expected[std::size_t(x)];
    // Binomial standard error of independent samples bounds the stratified estimator's error.
    const double sigma = std::sqrt(expected * (1.0 - expected) / spp / rows);
    EXPECT_NEAR(mean, expected, 4.0 * sigma + 1e-3) << "d = " << 1.25 * (x + 0.5) / columns;
  }
  EXPECT_NEAR(aoBesideWall(0.0, 1.0), 0.5, 1e-12); // in the corner half the cosine lobe is walled off
}

double rmse(const Image& im, const std::vector<double>& expected) {
  double sum = 0.0;
  for (std::size_t i = 0; i < expected.size(); ++i) sum += std::pow(im.pixels[i] - expected[i], 2.0);
  return std::sqrt(sum / double(expected.size()));
}

// Least-squares slope of log(error) against log(spp).
double fittedSlope(const std::vector<int>& spps, const std::vector<double>& errors) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = double(spps.size());
  for (std::size_t i = 0; i < spps.size(); ++i) {
    const double x = std::log(double(spps[i])), y = std::log(errors[i]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

TEST(Reference, ErrorFallsLikeInverseSqrtSpp) {
  // Points within R of the wall (every pixel has variance), 512 of them so the RMSE is itself
  // measured to a few percent.
  const WallCase c = wallCase(32, 16, 0.95f);
  const std::vector<int> spps = {4, 16, 64, 256};
  std::vector<double> independent, stratified;
  for (int spp : spps) {
    ReferenceOptions o = opts(spp, c.radius);
    o.stratified = false;
    independent.push_back(rmse(renderReference(c.scene, c.points, "ao", o), c.expected));
    o.stratified = true;
    stratified.push_back(rmse(renderReference(c.scene, c.points, "ao", o), c.expected));
  }
  // Plain Monte Carlo: error ~ spp^-1/2.
  const double slope = fittedSlope(spps, independent);
  RecordProperty("slope_independent", std::to_string(slope));
  RecordProperty("slope_stratified", std::to_string(fittedSlope(spps, stratified)));
  EXPECT_GE(slope, -0.6);
  EXPECT_LE(slope, -0.4);
  // Stratification never converges more slowly, and is not worse at any count.
  EXPECT_LE(fittedSlope(spps, stratified), -0.4);
  for (std::size_t i = 0; i < spps.size(); ++i) EXPECT_LE(stratified[i], independent[i] * 1.1) << spps[i];
}

TEST(Reference, IndirectFromALitPlaneIsAlbedoTimesIrradiance) {
  // A large plane 1 above the points, its underside lit by a directional light travelling up
  // (E0 = 2 lux, colour c). It fills the points' hemisphere with radiance rho/pi * E0 * c, so
  // E = rho * E0 * c; every cosine-weighted sample gives exactly that.
  Scene s;
  const glm::vec3 rho(0.5f, 0.25f, 0.8f), color(1.0f, 0.5f, 0.25f);
  addQuad(s, {0, 1, 0}, {1000, 0, 0}, {0, 0, 1000}, addMaterial(s, rho)); // faces down
  Light up = test::directional({0, 1, 0}, 2.0f, 0.0f);
  up.color = color;
  s.lights = {up};
  s.camera.position = {0, 0.5f, 3};
  const SurfaceData points = floorPoints(6);
  const Image e = renderReference(s, points, "indirect", opts(16));
  ASSERT_EQ(e.channels, 3);
  const glm::vec3 expected = rho * 2.0f * color;
  for (std::size_t i = 0; i < points.pixelCount(); ++i)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(e.pixels[i * 3 + k], expected[k], 1e-3f * expected[k]);

  // A base colour texture (sRGB 188 = 0.5 linear) multiplies the base colour, sampled at the hit.
  Scene textured = s;
  TextureImage t;
  t.width = t.height = 1;
  t.rgba8 = {188, 188, 188, 255};
  t.srgb = true;
  textured.textures.push_back(t);
  textured.materials[0].baseColorTexture = 0;
  const Image et = renderReference(textured, points, "indirect", opts(4));
  const float srgb188 = std::pow((188.0f / 255.0f + 0.055f) / 1.055f, 2.4f);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(et.pixels[std::size_t(k)], expected[k] * srgb188, 1e-3f * expected[k]);
  // Metals reflect no diffuse light.
  Scene metal = s;
  metal.materials[0].metallic = 1.0f;
  EXPECT_EQ(maxOf(renderReference(metal, points, "indirect", opts(4))), 0.0f);

  // Visibility on the second segment: a plane below the points shades the lit plane.
  Scene shaded = s;
  addQuad(shaded, {0, -1, 0}, {1000, 0, 0}, {0, 0, -1000});
  EXPECT_EQ(maxOf(renderReference(shaded, points, "indirect", opts(16))), 0.0f);
  // Visibility on the first segment: a black plane between the points and the lit one.
  Scene blocked = s;
  addQuad(blocked, {0, 0.5f, 0}, {1000, 0, 0}, {0, 0, 1000}, addMaterial(blocked, glm::vec3(0.0f)));
  EXPECT_EQ(maxOf(renderReference(blocked, points, "indirect", opts(16))), 0.0f);
}

TEST(Reference, IndirectUsesTheGpuLightModel) {
  // The bounce point's direct light follows lights.glsl: a spot lights only inside its cone, so
  // a spot aimed away from the only reflecting plane gives no indirect light, aimed at it some.
  Scene s;
  addQuad(s, {0, 1, 0}, {50, 0, 0}, {0, 0, 50}, addMaterial(s, glm::vec3(1.0f)));
  Light spot = test::point({0, 0.5f, 0}, 5.0f, 0.0f);
  spot.type = LightType::Spot;
  spot.direction = {0, -1, 0}; // away from the plane
  spot.innerConeAngle = 0.3f;
  spot.outerConeAngle = 0.5f;
  s.lights = {spot};
  s.camera.position = {0, 0.2f, 3};
  const SurfaceData points = floorPoints(4);
  EXPECT_EQ(maxOf(renderReference(s, points, "indirect", opts(16))), 0.0f);
  s.lights[0].direction = {0, 1, 0}; // towards it
  EXPECT_GT(maxOf(renderReference(s, points, "indirect", opts(16))), 0.0f);
}

TEST(Reference, DeterministicForASeedWhateverTheThreads) {
  const WallCase c = wallCase(40, 24, 1.2f); // several 16x16 tiles
  ReferenceOptions o = opts(8, c.radius);
  o.seed = 7;
  const Image many = renderReference(c.scene, c.points, "ao", o);
  Image one;
  tbb::task_arena single(1);
  single.execute([&] { one = renderReference(c.scene, c.points, "ao", o); });
  EXPECT_EQ(many.pixels, one.pixels);
  o.seed = 8;
  EXPECT_NE(renderReference(c.scene, c.points, "ao", o).pixels, many.pixels);
}

TEST(Reference, BackgroundIsZeroAndMasked) {
  Scene s = floorScene();
  s.lights = {test::directional({0, -1, 0}, 3, 2)};
  SurfaceData points = floorPoints(4);
  points.valid[5] = 0;
  points.position[5] = glm::vec3(0.0f);
  for (const char* aov : {"visibility", "ao", "indirect"}) {
    const Image im = renderReference(s, points, aov, opts(4));
    ASSERT_EQ(im.width, 4);
    ASSERT_EQ(im.height, 4);
    EXPECT_EQ(im.channels, std::string(aov) == "indirect" ? 3 : 1);
    ASSERT_EQ(im.mask.size(), 16u);
    for (std::size_t i = 0; i < 16; ++i) {
      EXPECT_EQ(im.mask[i], i == 5 ? 0.0f : 1.0f);
      if (i != 5) continue;
      for (int k = 0; k < im.channels; ++k) EXPECT_EQ(im.pixels[i * std::size_t(im.channels) + std::size_t(k)], 0.0f);
    }
  }
}

TEST(Reference, RejectsUnknownAovAndSampleCounts) {
  Scene s = floorScene();
  s.lights = {test::directional({0, -1, 0}, 3, 0)};
  const SurfaceData points = floorPoints(2);
  test::checkCaught(test::catchError([&] { renderReference(s, points, "color", opts(4)); }), ExitCode::Usage,
                    {"color", "visibility, ao, indirect"});
  test::checkCaught(test::catchError([&] { renderReference(s, points, "ao", opts(0)); }), ExitCode::Usage, {"1..65536"});
  test::checkCaught(test::catchError([&] { renderReference(s, points, "ao", opts(65537)); }), ExitCode::Usage,
                    {"65537"});
}

TEST(Reference, CountsRays) {
  Scene s = floorScene();
  s.lights = {test::directional({0, -1, 0}, 3, 0)};
  ReferenceStats stats;
  renderReference(s, floorPoints(4), "ao", opts(8), stats);
  EXPECT_EQ(stats.rays, 16u * 8u); // every direction above the plane is cast
  EXPECT_EQ(stats.triangles, 2u);
  renderReference(s, floorPoints(4), "visibility", opts(8), stats);
  EXPECT_EQ(stats.rays, 16u); // a light without extent: one ray per pixel
}

} // namespace
} // namespace rtlab
