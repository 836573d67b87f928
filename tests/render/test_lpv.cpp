// lpv (techniques/lpv/README.md): the SH and propagation arithmetic on the CPU model
// (techniques/lpv/lpv_model.h), then the technique's `indirect` on cornell and gi_wall: colour
// bleeding, what 0 and 64 iterations light, the leak through gi_wall's thin occluder against the
// cell size and occlusion, a moved light 0, other light types, and the error against the
// ray-traced reference. Bounds were measured on llvmpipe (values in the comments).
#include "app/reference_run.h"
#include "render_fixture.h"
#include "techniques/lpv/lpv_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace rtlab {
namespace {

constexpr float kPi = 3.14159265358979f;

// Sphere integral of f by a midpoint rule in (cos theta, phi).
template <typename F> double sphereIntegral(F f, int n = 400) {
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 2 * n; ++j) {
      const double z = -1.0 + (i + 0.5) * 2.0 / n, phi = (j + 0.5) * kPi / n;
      const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
      sum += f(glm::vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)));
    }
  return sum * (2.0 / n) * (kPi / n);
}

TEST(LpvModel, CosineLobeIsTheProjectionOfTheClampedCosine) {
  const glm::vec3 n = glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f));
  const lpv::Sh4 c = lpv::cosineLobe(n);
  for (int k = 0; k < 4; ++k) {
    const double projected =
        sphereIntegral([&](const glm::vec3& w) { return std::max(0.0f, glm::dot(n, w)) * lpv::shBasis(w)[k]; });
    EXPECT_NEAR(c[k], projected, 1e-3) << k;
  }
  // The flux of I = max(0, n.w) is pi, and band 0 alone keeps it.
  EXPECT_NEAR(lpv::shFlux(c), kPi, 1e-5);
  EXPECT_NEAR(lpv::shFlux(lpv::cosineLobe(n, 1)), kPi, 1e-5);
}

TEST(LpvModel, FaceSolidAnglesAreTheFacesSeenFromTheSourceCentre) {
  // The front face: a unit square at distance 1.5, 4 asin(a b / sqrt((a^2 + 4 d^2)(b^2 + 4 d^2))).
  EXPECT_NEAR(lpv::kFrontSolidAngle, 4.0 * std::asin(1.0 / 10.0), 1e-7);
  // A side face (x = 0.5, y in [-0.5, 0.5], z in [0.5, 1.5] from the source centre), integrated.
  const double side = sphereIntegral(
      [](const glm::vec3& w) {
        if (w.x <= 0.0f) return 0.0f;
        const float t = 0.5f / w.x; // the ray meets x = 0.5
        const float y = w.y * t, z = w.z * t;
        return std::abs(y) <= 0.5f && z >= 0.5f && z <= 1.5f ? 1.0f : 0.0f;
      },
      1600);
  EXPECT_NEAR(lpv::kSideSolidAngle, side, 2e-3);
  // Six neighbours times five faces cover the sphere: normalised to exactly 4 pi.
  const float k = lpv::solidAngleNormalisation();
  EXPECT_NEAR(6.0f * (lpv::kFrontSolidAngle + 4.0f * lpv::kSideSolidAngle), 4.0f * kPi, 3e-4f);
  EXPECT_NEAR(6.0f * k * (lpv::kFrontSolidAngle + 4.0f * lpv::kSideSolidAngle), 4.0f * kPi, 1e-5f);
  const auto faces = lpv::propagationFaces({0, 0, 1});
  EXPECT_EQ(faces[0].direction, glm::vec3(0, 0, 1));
  for (std::size_t f = 1; f < 5; ++f) {
    EXPECT_NEAR(faces[f].direction.z, 2.0f / std::sqrt(5.0f), 1e-6f) << f; // (d + e/2) normalised
    EXPECT_EQ(faces[f].normal.z, 0.0f) << f;
  }
}

TEST(LpvModel, OneStepConservesFluxInsideAndNeverGains) {
  // Random VPL-like cells (cosine lobes of random normal and flux) in the middle of a 9^3 grid:
  // one step keeps the band-0 flux (per-step energy 1) to float rounding; near the boundary the
  // light that leaves the grid is lost (energy < 1); 64 steps never gain and stay finite.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  lpv::Grid g(9);
  for (int i = 0; i < 20; ++i) {
    const glm::vec3 n = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(1e-3f));
    g.at(4, 4, 4) += (1.0f + u(rng)) / kPi * lpv::cosineLobe(n);
  }
  const float before = g.totalFlux();
  lpv::Grid once = lpv::propagate(g);
  EXPECT_NEAR(once.totalFlux() / before, 1.0f, 1e-5f);
  float previous = before;
  for (int step = 0; step < 64; ++step) {
    g = lpv::propagate(g);
    const float flux = g.totalFlux();
    ASSERT_TRUE(std::isfinite(flux));
    EXPECT_LE(flux, previous * (1.0f + 1e-5f)) << step;
    previous = flux;
  }
  // After 64 steps most light has left the 9^3 grid.
  EXPECT_LT(previous, 0.5f * before);
}

TEST(LpvModel, ClampingTheFacesNegativeFluxWouldGainEnergy) {
  // Why the step is not clamped (README "Energy"): a cosine lobe's 2-band SH, 1/4 + cos/2, is
  // negative behind it; clamping each face's flux at 0 counts that part as 0 instead of negative,
  // and one step then gains 13.8% of the flux. Unclamped, the gain is 0.
  const lpv::Sh4 lobe = lpv::cosineLobe({0, 0, 1});
  double clamped = 0.0, linear = 0.0;
  for (const glm::ivec3& d : lpv::axialDirections())
    for (const lpv::PropagationFace& f : lpv::propagationFaces(d)) {
      const double flux = f.solidAngle * lpv::shEval(lobe, f.direction);
      clamped += std::max(0.0, flux);
      linear += flux;
    }
  EXPECT_NEAR(linear / lpv::shFlux(lobe), 1.0, 1e-5);
  EXPECT_GT(clamped / lpv::shFlux(lobe), 1.13);
}

Image indirectOf(const TestFrame& f) {
  const TestRender r = renderTestFrame(f, {"indirect"});
  EXPECT_EQ(r.glErrors, 0);
  return r.renderer->readAov("indirect");
}

// Mean of channel c (or of all three for c = -1) over the surface pixels within `radius` pixels of
// the projection of `world`.
double meanAround(const TestFrame& f, const Image& img, const glm::vec3& world, int radius, int c) {
  int px = 0, py = 0;
  EXPECT_TRUE(projectToPixel(f, world, px, py)) << world.x << " " << world.y << " " << world.z;
  double sum = 0.0;
  int n = 0;
  for (int y = std::max(0, py - radius); y <= std::min(img.height - 1, py + radius); ++y)
    for (int x = std::max(0, px - radius); x <= std::min(img.width - 1, px + radius); ++x) {
      if (img.hasMask() && img.mask[std::size_t(y) * img.width + x] < 0.5f) continue;
      for (int k = 0; k < 3; ++k)
        if (c < 0 || c == k) sum += img.at(x, y, k) / (c < 0 ? 3.0 : 1.0);
      ++n;
    }
  return n ? sum / n : 0.0;
}

double meanOf(const Image& img) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < img.pixelCount(); ++i) {
    if (img.hasMask() && img.mask[i] < 0.5f) continue;
    for (int c = 0; c < 3; ++c)
      sum += img.pixels[i * 3 + c];
    n += 3;
  }
  return n ? sum / double(n) : 0.0;
}

bool allFinite(const Image& img) {
  for (float v : img.pixels)
    if (!std::isfinite(v)) return false;
  return true;
}

TEST(Lpv, CornellFloorBleedsRedNearTheRedWallAndGreenNearTheGreenWall) {
  // The floor 0.25 from each wall. Measured (96x54): R/G near red 1.63, near green 0.43; the
  // reference gives 3.66 and 0.53. LPV's is weaker: its white floor lights itself (README
  // "Artifacts"), which dilutes the walls' colour.
  const TestFrame f = makeTestFrame("cornell", "lpv", {}, 96, 54);
  const Image img = indirectOf(f);
  const glm::vec3 nearRed(-2.5f, 0.0f, 1.0f), nearGreen(2.5f, 0.0f, 1.0f);
  const double redSide = meanAround(f, img, nearRed, 1, 0) / meanAround(f, img, nearRed, 1, 1);
  const double greenSide = meanAround(f, img, nearGreen, 1, 0) / meanAround(f, img, nearGreen, 1, 1);
  std::printf("cornell floor R/G of indirect: near red %.3f, near green %.3f\n", redSide, greenSide);
  EXPECT_GT(redSide, 1.3);
  EXPECT_LT(greenSide, 0.6);
}

TEST(Lpv, ZeroIterationsLeaveTheReceiverDarkAndTheIteratesFluxFalls) {
  // gi_wall's receiver floor (x from 1.5 to 3) is outside light 0's cone and more than one cell
  // from every injected cell: with 0 iterations it gets exactly 0, with 32 light reaches it.
  // Then the increments of the summed volume: a step that conserved or gained energy would add as
  // much or more per iteration from 32 to 64 as from 16 to 32; the grid's boundary and the
  // occluders take light out, so it adds less (measured on cornell, 64x36: mean 0.147, 0.225, 0.309 at 8,
  // 16, 32: per step 0.0097, then 0.0052).
  const glm::vec3 receiver(2.2f, 0.0f, 0.0f);
  const TestFrame none = makeTestFrame("gi_wall", "lpv", {"lpv.iterations=0"}, 96, 54);
  EXPECT_EQ(meanAround(none, indirectOf(none), receiver, 3, -1), 0.0);
  const TestFrame some = makeTestFrame("gi_wall", "lpv", {"lpv.iterations=32"}, 96, 54);
  EXPECT_GT(meanAround(some, indirectOf(some), receiver, 3, -1), 0.0);

  std::vector<double> mean;
  for (int it : {8, 16, 32}) {
    const Image img = indirectOf(makeTestFrame("cornell", "lpv", {"lpv.iterations=" + std::to_string(it)}, 64, 36));
    ASSERT_TRUE(allFinite(img)) << it;
    mean.push_back(meanOf(img));
  }
  std::printf("cornell mean indirect at 8, 16, 32 iterations: %.4f %.4f %.4f\n", mean[0], mean[1], mean[2]);
  EXPECT_GT(mean[1], mean[0]);
  EXPECT_GT(mean[2], mean[1]);
  EXPECT_LT((mean[2] - mean[1]) / 16.0, 0.9 * (mean[1] - mean[0]) / 8.0);
}

// gi_wall: the red light on the floor just behind the thin occluder (x = -0.3) over the light
// just in front of it (x = -0.8), both 0.3 from the occluder's faces.
double leakBehindTheOccluder(const std::vector<std::string>& sets) {
  const TestFrame f = makeTestFrame("gi_wall", "lpv", sets, 96, 54);
  const Image img = indirectOf(f);
  double behind = 0.0, front = 0.0;
  for (float z : {-1.0f, -0.5f, 0.0f, 0.5f, 1.0f}) {
    behind += meanAround(f, img, {-0.2f, 0.0f, z}, 1, 0);
    front += meanAround(f, img, {-0.8f, 0.0f, z}, 1, 0);
  }
  return behind / front;
}

TEST(Lpv, ThinWallLeaksLessWithSmallerCellsAndWithOcclusion) {
  // Measured (96x54): grid 16 0.444, grid 32 0.292, grid 32 without occlusion 0.369. The steps
  // double with the grid so that light travels the same distance.
  const double leak16 = leakBehindTheOccluder({"lpv.grid=16", "lpv.iterations=8"});
  const double leak32 = leakBehindTheOccluder({"lpv.grid=32", "lpv.iterations=16"});
  const double leak32Open = leakBehindTheOccluder({"lpv.grid=32", "lpv.iterations=16", "lpv.occlusion=false"});
  std::printf("gi_wall leak behind/front: grid 16 %.3f, 32 %.3f; 32 without occlusion %.3f\n", leak16, leak32,
              leak32Open);
  EXPECT_LT(leak32, leak16);
  EXPECT_LT(leak32, leak32Open);
}

TEST(Lpv, MovingLightZeroChangesTheIndirectLight) {
  // The volume is rebuilt every frame from the frame's light-space G-buffer: the shared renderer
  // renders the scene's light, then light 0 moved along z (light0.position), then the scene's
  // light again, which must give the first image back (nothing stale).
  const TestFrame a = makeTestFrame("gi_wall", "lpv", {}, 64, 36);
  const Image first = indirectOf(a);
  const TestFrame moved = makeTestFrame("gi_wall", "lpv", {"light0.position=-1.5,3.5,1.5"}, 64, 36);
  const Image second = indirectOf(moved);
  const Image third = indirectOf(a);
  double changed = 0.0, repeated = 0.0;
  for (std::size_t i = 0; i < first.pixels.size(); ++i) {
    changed = std::max(changed, double(std::abs(second.pixels[i] - first.pixels[i])));
    repeated = std::max(repeated, double(std::abs(third.pixels[i] - first.pixels[i])));
  }
  std::printf("moving light 0: largest change %.4f, back again %.6f\n", changed, repeated);
  EXPECT_GT(changed, 0.05);
  EXPECT_EQ(repeated, 0.0);
}

TEST(Lpv, PointAndDirectionalLightZeroGiFiniteIndirectLight) {
  // Point light 0: a cube light-space G-buffer (six faces). Directional, in through the open front:
  // measured mean 0.62 (point) and 4.88 (directional: the VPLs on the outside of the box leak in
  // through walls on cell faces at lpv.lookup_offset 0; 0.09 at 0.5, README "Artifacts").
  for (LightType type : {LightType::Point, LightType::Directional}) {
    TestFrame f = makeTestFrame("cornell", "lpv", {}, 64, 36);
    Light& l = f.scene.lights[0];
    l.type = type;
    if (type == LightType::Directional) {
      l.intensity = 3.0f;                                          // lux, the key irradiance of the built-in scenes
      l.direction = glm::normalize(glm::vec3(0.3f, -0.6f, -1.0f)); // in through the open front
    }
    f.scene.name = type == LightType::Point ? "cornell_point" : "cornell_directional";
    const Image img = indirectOf(f);
    EXPECT_TRUE(allFinite(img)) << f.scene.name;
    const double mean = meanOf(img);
    std::printf("%s: mean indirect %.4f\n", f.scene.name.c_str(), mean);
    EXPECT_GT(mean, 0.01) << f.scene.name;
  }
}

TEST(Lpv, ErrorAgainstTheReferenceOnCornell) {
  const TestFrame f = makeTestFrame("cornell", "lpv", {}, 64, 36);
  const TestRender r = renderTestFrame(f, {"indirect"});
  const Image got = r.renderer->readAov("indirect");
  const Image ref = renderReferenceFrame(*r.renderer, resolvedOf(f), "indirect", 256, false);
  double err2 = 0.0, ref2 = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < ref.pixelCount(); ++i) {
    if (ref.mask[i] < 0.5f) continue;
    for (int c = 0; c < 3; ++c) {
      const double a = got.pixels[i * 3 + c], b = ref.pixels[i * 3 + c];
      err2 += (a - b) * (a - b);
      ref2 += b * b;
      ++n;
    }
  }
  const double rmse = std::sqrt(err2 / double(n)), none = std::sqrt(ref2 / double(n));
  std::printf("cornell lpv rmse %.4f, no indirect light %.4f\n", rmse, none);
  // Measured 0.579 against 0.631 for no indirect light at all (64x36; the reference's own noise at
  // 256 spp is about 0.03, docs/measuring.md). The error is LPV's, not the reference's: too few
  // iterations to reach the ceiling from the floor, the floor lighting itself, the 2-band lobes
  // (techniques/lpv/README.md "Error"). The bound is the measured value plus 10%, and it must beat
  // leaving the indirect light out.
  EXPECT_LT(rmse, 0.64);
  EXPECT_LT(rmse, none);
}

// Off is free: without lpv no lpv or light-space G-buffer pass runs and no such resource exists;
// with it the debug views are culled unless requested, and 0 iterations add no propagation or
// geometry volume.
TEST(Lpv, OffIsFreeAndUnrequestedPartsAreCulled) {
  TestRender off = renderTestFrame(makeTestFrame("cornell", "", {}, 64, 36), {"color"});
  EXPECT_FALSE(ranPass(*off.renderer, "lpv"));
  EXPECT_FALSE(ranPass(*off.renderer, "rsm"));
  EXPECT_FALSE(hasResource(*off.renderer, "lpv"));
  EXPECT_FALSE(hasResource(*off.renderer, "rsm"));
  TestRender on = renderTestFrame(makeTestFrame("cornell", "lpv", {}, 64, 36), {"color"});
  EXPECT_TRUE(ranPass(*on.renderer, "lpv.propagate8"));
  EXPECT_FALSE(ranPass(*on.renderer, "lpv.propagate9"));
  EXPECT_TRUE(ranPass(*on.renderer, "lpv.geometry"));
  EXPECT_TRUE(ranPass(*on.renderer, "lpv.lookup"));
  EXPECT_FALSE(ranPass(*on.renderer, "lpv.slice"));
  EXPECT_FALSE(ranPass(*on.renderer, "lpv.injected"));
  TestRender none = renderTestFrame(makeTestFrame("cornell", "lpv", {"lpv.iterations=0"}, 64, 36), {"color"});
  EXPECT_FALSE(ranPass(*none.renderer, "lpv.propagate"));
  EXPECT_FALSE(ranPass(*none.renderer, "lpv.geometry"));
  EXPECT_FALSE(hasResource(*none.renderer, "lpv.sum"));
  TestRender view = renderTestFrame(makeTestFrame("cornell", "lpv", {}, 64, 36), {"lpv.slice"});
  EXPECT_TRUE(ranPass(*view.renderer, "lpv.slice"));
}

} // namespace
} // namespace rtlab
