// rsm (techniques/rsm/README.md) and the light-space G-buffer it shares with lpv
// (techniques/common/rsm/rsm_gbuffer.h): absolute units against closed-form integrals for an
// orthographic and a cube map, colour bleeding in cornell, convergence of the pattern towards the
// all-texel sum, independence of the map resolution, the error against the ray-traced reference,
// VPLs behind the receiver, every light type, and off is free.
#include "app/reference_run.h"
#include "frame/frame_view.h"
#include "frame/param_catalog.h"
#include "frame/registry.h"
#include "frame/selection.h"
#include "render/renderer.h"
#include "render_fixture.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"
#include "scene/scene_params.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace rtlab {
namespace {

constexpr double kPi = 3.14159265358979;
constexpr float kAlbedo = 0.5f;

Image indirect(const TestFrame& f) {
  const TestRender r = renderTestFrame(f, {"indirect"});
  EXPECT_EQ(r.glErrors, 0);
  return r.renderer->readAov("indirect");
}

double meanOf(const Image& img) {
  double sum = 0.0;
  for (float v : img.pixels)
    sum += v;
  return sum / double(img.pixels.size());
}

// Over the surface pixels of `b` when it has a mask (a reference), else over all.
double rmse(const Image& a, const Image& b) {
  double sum = 0.0, n = 0.0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const std::size_t px = i / std::size_t(b.channels);
    if (!b.mask.empty() && b.mask[px] < 0.5f) continue;
    sum += double(a.pixels[i] - b.pixels[i]) * (a.pixels[i] - b.pixels[i]);
    n += 1.0;
  }
  return std::sqrt(sum / n);
}

glm::vec3 pixelOf(const Image& img, int x, int y) {
  const std::size_t i = (std::size_t(y) * std::size_t(img.width) + std::size_t(x)) * 3;
  return {img.pixels[i], img.pixels[i + 1], img.pixels[i + 2]};
}

// A 2 x 2 floor (x in [0, 2], z in [-1, 1], albedo 0.5) and a wall on its x = 0 edge (y in
// [0, 2], facing +x, albedo 0.5), lit by `light`; the camera looks at the wall from the floor's
// side (`behind`: from the other side).
TestFrame floorAndWall(const std::string& name, const Light& light, bool behind, const std::vector<std::string>& sets,
                       int w, int h) {
  builtin::SceneBuilder b(name);
  const int white = b.addMaterial(builtin::diffuseMaterial("white", glm::vec3(kAlbedo)));
  b.addObject(makeQuad("floor", {1, 0, 0}, {1, 0, 0}, {0, 0, -1}), white);
  b.addObject(makeQuad("wall", {0, 1, 0}, {0, 0, -1}, {0, 1, 0}), white);
  b.addLight(light);
  const glm::vec3 eye = behind ? glm::vec3(-3.0f, 1.0f, 1.5f) : glm::vec3(3.5f, 1.2f, 2.0f);
  TestFrame f;
  f.scene = b.finish(builtin::camera(eye, {0, 0.6f, 0}, 45.0f));
  f.params = makeParamSet(f.scene, TechniqueRegistry::instance());
  TechniqueSelection selection(TechniqueRegistry::instance());
  selection.activateList("rsm");
  f.techniques = selection.ordered();
  for (const auto& s : sets)
    f.params.setAssignment(s);
  applySceneParams(f.params, f.scene);
  f.width = w;
  f.height = h;
  return f;
}

// The world point of the wall (x = 0) seen through pixel (x, y).
glm::vec3 wallPointAt(const TestFrame& f, int x, int y) {
  const FrameView v = makeFrameView(f.scene.camera, f.width, f.height);
  const glm::mat4 inv = glm::inverse(v.viewProj);
  const glm::vec2 ndc((float(x) + 0.5f) / float(f.width) * 2.0f - 1.0f,
                      (float(f.height - 1 - y) + 0.5f) / float(f.height) * 2.0f - 1.0f);
  glm::vec4 a = inv * glm::vec4(ndc, -1.0f, 1.0f), b = inv * glm::vec4(ndc, 1.0f, 1.0f);
  const glm::vec3 p0 = glm::vec3(a) / a.w, p1 = glm::vec3(b) / b.w;
  return p0 + (p1 - p0) * (-p0.x / (p1.x - p0.x));
}

// The one-bounce irradiance at wall point (0, y, z) from the floor, whose irradiance is
// `floorIrradiance(x, z)`, over the floor points within `radius` of (0, z0) (the map disc), by the
// midpoint rule on a 1000 x 1000 grid:
//   E = (rho / pi) * integral of E_floor(x_p) * y * x / |x - x_p|^4 dA.
template <typename F> double wallIrradiance(double y, double z0, double radius, F floorIrradiance) {
  constexpr int n = 1000;
  const double dx = 2.0 / n, dz = 2.0 / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) {
      const double x = (i + 0.5) * dx, z = -1.0 + (k + 0.5) * dz;
      if (x * x + (z - z0) * (z - z0) > radius * radius) continue;
      const double d2 = x * x + y * y + (z - z0) * (z - z0);
      sum += floorIrradiance(x, z) * y * x / (d2 * d2) * dx * dz;
    }
  return kAlbedo / kPi * sum;
}

// Absolute units of the G-buffer's flux (Phi_p = rho E_perp A_perp) and of the VPL sum, for an
// orthographic map: a directional light of 3 lux straight down lights the floor only (the wall is
// edge-on). At wall points the all-texel sum (128^2 map, r_max 0.5) equals the closed-form integral
// over the floor within the disc (the map is 2 r wide, r the light space's fitted radius) within
// 1% (measured +0.10%, +0.47%, +0.60%; at 256^2 -0.04%, -0.15%, -0.18%).
TEST(Rsm, DirectionalLightMatchesTheClosedFormIntegral) {
  const TestFrame f =
      floorAndWall("rsm_floor_wall_directional", builtin::directionalLight("key", {0, -1, 0}, 3.0f, 0.5f), false,
                   {"rsm.sampling=all_texels", "rsm.r_max=0.5", "rsm.resolution=128", "rsm.indirect_scale=1",
                    "rsm.distance_clamp=0"},
                   64, 48);
  const Image img = indirect(f);
  const float mapRadius = 1.01f * std::max(f.scene.worldBounds().radius(), 1e-3f);
  int checked = 0;
  for (const glm::vec3 target : {glm::vec3(0, 0.4f, 0), glm::vec3(0, 0.8f, 0.3f), glm::vec3(0, 1.5f, -0.4f)}) {
    int x, y;
    ASSERT_TRUE(projectToPixel(f, target, x, y));
    const glm::vec3 p = wallPointAt(f, x, y);
    const double expected = wallIrradiance(p.y, p.z, 0.5 * 2.0 * mapRadius, [](double, double) { return 3.0; });
    const double got = pixelOf(img, x, y).x;
    std::printf("directional: wall point (%.3f, %.3f): rsm %.5f, closed form %.5f (%+.2f%%)\n", p.y, p.z, got, expected,
                100.0 * (got / expected - 1.0));
    EXPECT_NEAR(got, expected, 0.01 * expected);
    ++checked;
  }
  EXPECT_EQ(checked, 3);
}

// The same for a cube map (a point light of 20 cd at (1, 3, 0): the floor lies in the -Y face,
// the texels' A_perp = d^2 texelScale^2 cos^3): floor irradiance I cos(theta) / d^2, the whole
// floor within the disc (r_max 0.5 around the wall points' projections covers it). Within 1% with
// a 256^2 map (measured +0.17%, +0.48%; -0.5%, -1.03% at 128^2); 32 x 24 pixels keep it fast.
TEST(Rsm, PointLightMatchesTheClosedFormIntegral) {
  const glm::vec3 light(1, 3, 0);
  const TestFrame f = floorAndWall("rsm_floor_wall_point", builtin::pointLight("key", light, 20.0f, 0.0f), false,
                                   {"rsm.sampling=all_texels", "rsm.r_max=0.5", "rsm.resolution=256",
                                    "rsm.indirect_scale=1", "rsm.distance_clamp=0"},
                                   32, 24);
  const Image img = indirect(f);
  auto floorIrradiance = [&](double x, double z) {
    const double dx = light.x - x, dy = light.y, dz = light.z - z, d2 = dx * dx + dy * dy + dz * dz;
    return 20.0 * (dy / std::sqrt(d2)) / d2;
  };
  for (const glm::vec3 target : {glm::vec3(0, 0.4f, 0), glm::vec3(0, 0.8f, 0.3f)}) {
    int x, y;
    ASSERT_TRUE(projectToPixel(f, target, x, y));
    const glm::vec3 p = wallPointAt(f, x, y);
    const double expected = wallIrradiance(p.y, p.z, 10.0, floorIrradiance);
    const double got = pixelOf(img, x, y).x;
    std::printf("point: wall point (%.3f, %.3f): rsm %.5f, closed form %.5f (%+.2f%%)\n", p.y, p.z, got, expected,
                100.0 * (got / expected - 1.0));
    EXPECT_NEAR(got, expected, 0.01 * expected);
  }
}

// A VPL behind the receiver adds nothing: the wall's back (facing -x) sees the floor's VPLs
// behind its normal, so its indirect light is exactly 0, while the front has some.
TEST(Rsm, VplsBehindTheReceiverAddNothing) {
  const Light light = builtin::directionalLight("key", {0, -1, 0}, 3.0f, 0.5f);
  const TestFrame back =
      floorAndWall("rsm_floor_wall_back", light, true, {"rsm.indirect_scale=1", "rsm.r_max=0.5"}, 96, 72);
  const Image img = indirect(back);
  int x, y;
  ASSERT_TRUE(projectToPixel(back, {0, 0.8f, 0}, x, y));
  EXPECT_EQ(pixelOf(img, x, y), glm::vec3(0.0f));
  const TestFrame front =
      floorAndWall("rsm_floor_wall_front", light, false, {"rsm.indirect_scale=1", "rsm.r_max=0.5"}, 96, 72);
  ASSERT_TRUE(projectToPixel(front, {0, 0.8f, 0}, x, y));
  EXPECT_GT(pixelOf(indirect(front), x, y).x, 0.1f);
}

// The mean of `img` over the (2k+1)^2 pixels around (x, y).
glm::dvec3 around(const Image& img, int x, int y, int k) {
  glm::dvec3 sum(0.0);
  int n = 0;
  for (int j = -k; j <= k; ++j)
    for (int i = -k; i <= k; ++i) {
      sum += glm::dvec3(pixelOf(img, std::clamp(x + i, 0, img.width - 1), std::clamp(y + j, 0, img.height - 1)));
      ++n;
    }
  return sum / double(n);
}

// Colour bleeding in cornell at the defaults: the floor beside the red wall (x = -2.5) gets
// red-tinted bounce light, beside the green wall (x = 2.5) green-tinted (the red wall's albedo is
// (0.63, 0.065, 0.05), the green one's (0.14, 0.45, 0.091)). Measured red/green 9.7 and 0.31.
TEST(Rsm, CornellFloorBleedsTheWallColours) {
  const TestFrame f = makeTestFrame("cornell", "rsm", {}, 160, 90);
  const Image img = indirect(f);
  int x, y;
  ASSERT_TRUE(projectToPixel(f, {-2.5f, 0.0f, 2.2f}, x, y));
  const glm::dvec3 red = around(img, x, y, 1);
  ASSERT_TRUE(projectToPixel(f, {2.5f, 0.0f, 2.2f}, x, y));
  const glm::dvec3 green = around(img, x, y, 1);
  std::printf("floor beside the red wall %.4f %.4f %.4f, beside the green wall %.4f %.4f %.4f\n", red.x, red.y, red.z,
              green.x, green.y, green.z);
  ASSERT_GT(red.y, 0.0);
  ASSERT_GT(green.y, 0.0);
  EXPECT_GT(red.x / red.y, 2.0);
  EXPECT_LT(green.x / green.y, 0.5);
}

// The pattern converges to the all-texel sum (cornell, 128^2 map, r_max 0.1, exponent 1): the
// RMSE falls from 16 to 64 to 400 samples, exponent 1 is unbiased (image mean within 1% of the
// sum's) and exponent 2 (published) is not: it over-weights the rim, whose VPLs lie farther from
// the receiver, so its mean is lower. Measured RMSE 0.0209, 0.0070, 0.0019 (the sum's mean
// 0.0212); means +0.05%, +0.3%, +0.05%; exponent 2 -14.6%.
TEST(Rsm, PatternConvergesToTheAllTexelSum) {
  const std::vector<std::string> base = {"rsm.resolution=128", "rsm.weight_exponent=1"};
  TestFrame all = makeTestFrame("cornell", "rsm", base, 160, 90);
  all.params.setAssignment("rsm.sampling=all_texels");
  const Image sum = indirect(all);
  double previous = 1e30;
  for (int samples : {16, 64, 400}) {
    TestFrame f = makeTestFrame("cornell", "rsm", base, 160, 90);
    f.params.setAssignment("rsm.samples=" + std::to_string(samples));
    const Image img = indirect(f);
    const double e = rmse(img, sum);
    std::printf("samples %d: rmse %.5f (all-texel mean %.5f), mean %.5f\n", samples, e, meanOf(sum), meanOf(img));
    EXPECT_LT(e, previous) << samples;
    previous = e;
    if (samples == 400) {
      EXPECT_NEAR(meanOf(img), meanOf(sum), 0.01 * meanOf(sum));
      f.params.setAssignment("rsm.weight_exponent=2");
      const double biased = meanOf(indirect(f));
      std::printf("exponent 2: mean %.5f (%+.1f%% of the all-texel sum)\n", biased,
                  100.0 * (biased / meanOf(sum) - 1.0));
      EXPECT_LT(biased, 0.9 * meanOf(sum));
    }
  }
}

// The map resolution changes the mean indirect light little (cornell, exponent 1, 1024 samples):
// 256 vs 1024 within 2% (measured +0.32%). At 64 the mean is lower (measured -5.7%; -7.4% with the
// all-texel sum): the blocks'
// contact edges, where a point VPL at the centre of a coarse texel of the block's side is seen at
// grazing angle from the floor next to it and underestimates the patch (techniques/rsm/README.md
// "Artifacts").
TEST(Rsm, MapResolutionChangesTheMeanLittle) {
  auto meanAt = [](int resolution) {
    const TestFrame f = makeTestFrame(
        "cornell", "rsm", {"rsm.resolution=" + std::to_string(resolution), "rsm.weight_exponent=1", "rsm.samples=1024"},
        160, 90);
    return meanOf(indirect(f));
  };
  const double m64 = meanAt(64), m256 = meanAt(256), m1024 = meanAt(1024);
  std::printf("mean indirect: 64^2 %.5f (%+.2f%%), 256^2 %.5f (%+.2f%%), 1024^2 %.5f\n", m64,
              100.0 * (m64 / m1024 - 1.0), m256, 100.0 * (m256 / m1024 - 1.0), m1024);
  EXPECT_NEAR(m256, m1024, 0.02 * m1024);
  EXPECT_NEAR(m64, m1024, 0.10 * m1024);
}

// Against the ray-traced reference on cornell (80 x 45, 1024 spp: its own noise, about 0.014 RMSE
// per docs/measuring.md's table, is under 5% of rsm's error). rsm misses most of the indirect
// light there: the light is a wide spot, so the map is a cube, and a receiver's disc of r_max
// around its projection holds only surfaces seen in about the same direction from the light (the
// ceiling, on the +Y face, never sees the floor on the -Y face); and it has no visibility. The
// bounds are the measured errors (printout) plus 10%; rsm must beat "no indirect light" and a
// larger disc must help. RMSE over the reference's surface pixels.
TEST(Rsm, ErrorAgainstTheReferenceOnCornell) {
  const TestFrame f = makeTestFrame("cornell", "rsm", {}, 80, 45);
  TestRender r = renderTestFrame(f, {"indirect"});
  const Image ref = renderReferenceFrame(*r.renderer, resolvedOf(f), "indirect", 1024, false);
  Image zero = ref;
  std::fill(zero.pixels.begin(), zero.pixels.end(), 0.0f);
  const double none = rmse(zero, ref);
  const double standard = rmse(indirect(f), ref);
  TestFrame wide = f;
  wide.params.setAssignment("rsm.r_max=0.5");
  wide.params.setAssignment("rsm.weight_exponent=1");
  const double large = rmse(indirect(wide), ref);
  std::printf("rmse against the reference (mean %.4f): no indirect %.4f, rsm defaults %.4f, r_max 0.5 exponent 1 "
              "%.4f\n",
              meanOf(ref), none, standard, large);
  EXPECT_LT(standard, none);
  EXPECT_LT(large, standard);
  constexpr double kMeasuredDefault = 0.611, kMeasuredLarge = 0.516; // no indirect light: 0.636
  EXPECT_LT(standard, 1.1 * kMeasuredDefault);
  EXPECT_LT(large, 1.1 * kMeasuredLarge);
}

// The distance clamp caps the corners' 1/|d|^4 terms: with the all-texel sum on a 128^2 map
// (cornell, full resolution) the largest pixel falls as the clamp grows from 0 to 1 to 2 texel
// footprints (measured 1.31, 1.06, 0.92) while the image mean moves by a few percent only
// (measured -2.1% and -6.2% against no clamp): the clamp acts where VPLs lie near.
TEST(Rsm, DistanceClampCapsTheCorners) {
  double previousMax = 1e30, mean0 = 0.0;
  for (const char* clamp : {"0", "1", "2"}) {
    const Image img = indirect(makeTestFrame("cornell", "rsm",
                                             {"rsm.resolution=128", "rsm.sampling=all_texels", "rsm.indirect_scale=1",
                                              std::string("rsm.distance_clamp=") + clamp},
                                             160, 90));
    const double largest = *std::max_element(img.pixels.begin(), img.pixels.end());
    const double mean = meanOf(img);
    if (mean0 == 0.0) mean0 = mean;
    std::printf("distance clamp %s: max %.4f, mean %.5f\n", clamp, largest, mean);
    EXPECT_LT(largest, previousMax) << clamp;
    EXPECT_NEAR(mean, mean0, 0.1 * mean0) << clamp;
    previousMax = largest;
  }
}

// Every kind of light 0 gives finite, non-zero indirect light: directional (stacked, an
// orthographic map), spot (contact, one perspective map), wide spot (cornell, a cube).
TEST(Rsm, EveryLightTypeGivesFiniteNonZeroIndirect) {
  for (const char* scene : {"stacked", "contact", "cornell"}) {
    const Image img = indirect(makeTestFrame(scene, "rsm", {"rsm.samples=64"}, 64, 36));
    double sum = 0.0;
    for (float v : img.pixels) {
      ASSERT_TRUE(std::isfinite(v)) << scene;
      sum += v;
    }
    EXPECT_GT(sum, 0.0) << scene;
  }
}

// A rectangular light 0 has no light-space projection: a usage error (exit 2) with one line naming
// it, as the shadow stage gives, not a crash or a silent black frame.
TEST(Rsm, RectangularLightZeroIsAUsageError) {
  Light rect;
  rect.name = "rect";
  rect.type = LightType::Rect;
  rect.position = {1, 1.5f, 0};
  rect.direction = {0, -1, 0};
  rect.right = {1, 0, 0};
  rect.up = {0, 0, 1};
  rect.width = rect.height = 0.5f;
  rect.intensity = 5.0f;
  const TestFrame f = floorAndWall("rsm_floor_wall_rect", rect, false, {}, 32, 24);
  try {
    renderTestFrame(f, {"indirect"});
    ADD_FAILURE() << "no error for a rectangular light 0";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::Usage);
    EXPECT_NE(std::string(e.what()).find("light 0 is rectangular: the light-space G-buffer"), std::string::npos) << e.what();
  }
}

// Off is free: without rsm no rsm pass runs and no rsm resource exists; with it both do, and the
// debug views' passes run only when asked for.
TEST(Rsm, OffIsFree) {
  TestRender off = renderTestFrame(makeTestFrame("cornell", "", {}, 64, 36), {"color", "indirect"});
  EXPECT_FALSE(ranPass(*off.renderer, "rsm"));
  EXPECT_FALSE(hasResource(*off.renderer, "rsm"));
  TestRender on = renderTestFrame(makeTestFrame("cornell", "rsm", {"rsm.samples=16"}, 64, 36), {"color"});
  EXPECT_TRUE(ranPass(*on.renderer, "rsm.indirect"));
  EXPECT_TRUE(hasResource(*on.renderer, "rsm.flux"));
  EXPECT_FALSE(ranPass(*on.renderer, "rsm.flux"));
  EXPECT_FALSE(ranPass(*on.renderer, "rsm.view_vpl_count"));
  TestRender views =
      renderTestFrame(makeTestFrame("cornell", "rsm", {"rsm.samples=16"}, 64, 36), {"rsm.flux", "rsm.vpl_count"});
  EXPECT_EQ(views.glErrors, 0);
  EXPECT_TRUE(ranPass(*views.renderer, "rsm.flux"));
  EXPECT_TRUE(ranPass(*views.renderer, "rsm.view_vpl_count"));
}
} // namespace
} // namespace rtlab
