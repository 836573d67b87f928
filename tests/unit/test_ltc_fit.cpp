// The LTC fitter (tools/ltc_fit) and the committed table assets/ltc/ggx.json (assets/ltc/README.md):
// the fitter reproduces committed cells from scratch, the committed fit error is below a measured
// bound per roughness band and agrees with an independent estimate, the magnitude and Fresnel
// parts match an independent quadrature of the frame's BRDF, the sphere table has its closed-form
// values where the cap is unclipped or fully below the horizon, and the fit is deterministic
// whatever the thread count.
#include "ltc_fit.h"
#include "ltc_lobe.h"
#include "sphere_form_factor.h"

#include "shading/brdf_model.h"
#include "techniques/common/arealight/ltc_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace rtlab;
using namespace rtlab::ltcfit;

namespace {

const LtcTable& committed() {
  static const LtcTable table = LtcTable::load(RTLAB_SOURCE_DIR "/assets/ltc/ggx.json");
  return table;
}

glm::dmat3 storedM(const LtcTable& t, int i, int j) {
  const auto abcd = t.mInvAt(i, j);
  return glm::inverse(unpackInverse({abcd[0], abcd[1], abcd[2], abcd[3]}));
}

// Integral over the hemisphere of f(l) by the midpoint rule in (cos(theta), phi): uniform in solid
// angle, independent of the GGX importance sampling the fitter uses.
template <class F> double hemisphereQuadrature(const F& f, int nCos, int nPhi) {
  double sum = 0.0;
  for (int a = 0; a < nCos; ++a) {
    const double c = (a + 0.5) / nCos, s = std::sqrt(1.0 - c * c);
    for (int b = 0; b < nPhi; ++b) {
      const double phi = 2.0 * brdf::kPi * (b + 0.5) / nPhi;
      sum += f(glm::dvec3(s * std::cos(phi), s * std::sin(phi), c));
    }
  }
  return sum * 2.0 * brdf::kPi / (double(nCos) * nPhi);
}

} // namespace

TEST(LtcFit, CommittedTableHasTheDefaultGrid) {
  const LtcTable& t = committed();
  EXPECT_EQ(t.size, 64);
  EXPECT_EQ(t.samples, 1024);
  EXPECT_EQ(t.seed, 1u);
}

// The fitter run from scratch on a few cells, warm-started from the committed neighbour (the
// rougher cell of the same view row, as fitTable chains them), gives the committed lobe. The
// moments use the table's seed, so they are recomputed exactly; the fit starts from the
// neighbour's parameters as stored (floats, M^-1 normalised), not from the doubles the fit carried,
// so Nelder-Mead may stop at a slightly different point. Measured: the refit lobes differ from the
// committed ones by 2e-8 to 1.1e-7 (L1: the floats' rounding), neighbouring cells' lobes by 0.039
// to 0.17 (checked below: > 0.03, so staying at the neighbour fails), and a crippled optimiser
// (20 evaluations per Nelder-Mead run instead of 400) lands 0.004 to 0.0097 away. The bound, 1e-3,
// sits between: far above the rounding, below a fit that stopped early.
TEST(LtcFit, ReproducesCommittedCellsFromScratch) {
  const LtcTable& t = committed();
  const int n = t.size;
  struct Cell {
    int i, j;
  };
  for (const Cell c : {Cell{12, 8}, Cell{40, 20}, Cell{24, 44}, Cell{56, 56}}) {
    SCOPED_TRACE("cell i=" + std::to_string(c.i) + " j=" + std::to_string(c.j));
    const auto neighbour = t.mInvAt(c.i + 1, c.j);
    const LobeMoments neighbourMoments = cellMoments(c.i + 1, c.j, n, t.samples, t.seed);
    const LtcParams start =
        paramsFromInverse({neighbour[0], neighbour[1], neighbour[2], neighbour[3]}, neighbourMoments.averageDir);
    const CellFit fit = fitCell(c.i, c.j, n, start, t.samples, t.seed);
    EXPECT_FLOAT_EQ(float(fit.moments.magnitude), t.magnitudeAt(c.i, c.j));
    EXPECT_FLOAT_EQ(float(fit.moments.fresnel), t.fresnelAt(c.i, c.j));
    const glm::dmat3 refit = glm::inverse(unpackInverse(fit.mInv));
    const double difference = ltcL1Difference(refit, storedM(t, c.i, c.j), 4096, 7);
    EXPECT_LT(difference, 1e-3);
    // ... while the neighbour's lobe is measurably another one.
    EXPECT_GT(ltcL1Difference(storedM(t, c.i + 1, c.j), storedM(t, c.i, c.j), 4096, 7), 0.03);
  }
}

// At low roughness the LTC is the mirror lobe: M maps +z to (about) the reflection of v, which lies
// toward -x in the table's frame (v toward +x). This pins the frame convention the shaders use.
TEST(LtcFit, SharpLobesPointAtTheMirrorDirection) {
  const LtcTable& t = committed();
  for (int j : {0, 16, 32, 48}) {
    const double c = LtcTable::cosThetaAt(j, t.size);
    const glm::dvec3 mirror(-std::sqrt(1.0 - c * c), 0.0, c);
    const glm::dvec3 peak = glm::normalize(storedM(t, 0, j) * glm::dvec3(0.0, 0.0, 1.0));
    EXPECT_GT(glm::dot(peak, mirror), 0.999) << "row " << j;
  }
}

// The committed fit error (L1 between the normalised lobe and the LTC, assets/ltc/README.md) stays
// below the bound measured per roughness band, over every view angle but the grazing rows
// (cos(theta_v) < 0.1, j >= 60), whose own bound is separate. The bounds are the measured maxima
// (0.397, 0.594, 0.576, 0.313; grazing 1.276, 0.971, 0.945, 0.443) raised by about 20%: the same
// fit with 256 samples instead of 1024 (the first committed table) exceeds four of the eight
// (0.754 in [0.25, 0.5); grazing 2.553, 1.422, 0.682).
TEST(LtcFit, CommittedErrorBelowMeasuredBoundPerRoughnessBand) {
  const LtcTable& t = committed();
  const int n = t.size;
  struct Band {
    double rMin, rMax, bound, grazingBound;
  };
  const Band bands[] = {{0.0, 0.25, 0.48, 1.55}, {0.25, 0.5, 0.72, 1.17}, {0.5, 0.75, 0.70, 1.14}, {0.75, 1.0001, 0.38, 0.54}};
  for (const Band& band : bands) {
    double worst = 0.0, worstGrazing = 0.0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double r = LtcTable::roughnessAt(i, n);
        if (r < band.rMin || r >= band.rMax) continue;
        (LtcTable::cosThetaAt(j, n) < 0.1 ? worstGrazing : worst) =
            std::max(LtcTable::cosThetaAt(j, n) < 0.1 ? worstGrazing : worst, double(t.errorAt(i, j)));
      }
    EXPECT_LT(worst, band.bound) << "roughness [" << band.rMin << ", " << band.rMax << ")";
    EXPECT_LT(worstGrazing, band.grazingBound) << "grazing, roughness [" << band.rMin << ", " << band.rMax << ")";
  }
}

// The stored error is what it says: an independent estimate (another seed, 8x the samples) of the
// L1 difference between the stored LTC and the normalised lobe agrees within the estimators' noise
// (measured: within 0.0026 at these cells).
TEST(LtcFit, StoredErrorMatchesAnIndependentEstimate) {
  const LtcTable& t = committed();
  for (const auto& [i, j] : {std::pair{8, 8}, std::pair{30, 30}, std::pair{50, 45}, std::pair{63, 60}}) {
    const double alpha = brdf::alphaFromRoughness(LtcTable::roughnessAt(i, t.size));
    const double c = LtcTable::cosThetaAt(j, t.size);
    const double independent = lobeL1Error(alpha, c, t.magnitudeAt(i, j), storedM(t, i, j), 8 * t.samples, 12345);
    EXPECT_NEAR(independent, t.errorAt(i, j), 0.004 + 0.05 * independent) << "cell i=" << i << " j=" << j;
  }
}

// magnitude and fresnel against a uniform-in-solid-angle quadrature of D V cos (and of D V cos
// (1 - v.h)^5): cells rough enough for 1024 x 512 points to resolve the lobe (r >= 0.4; doubling
// the points changes the quadrature by < 2e-5). Measured: the table's values (16384 GGX samples)
// are within 1.5e-4 of it relative to the magnitude (7.4e-4 at a near-grazing cell, (30, 60)); the
// bounds are 2e-3 and, for the Fresnel part, 2e-4 of the magnitude (measured 4e-5).
TEST(LtcFit, MagnitudeAndFresnelMatchAnIndependentQuadrature) {
  const LtcTable& t = committed();
  const glm::dvec3 n(0.0, 0.0, 1.0);
  for (const auto& [i, j] : {std::pair{26, 0}, std::pair{40, 30}, std::pair{63, 10}, std::pair{50, 50}, std::pair{30, 60}}) {
    const double alpha = brdf::alphaFromRoughness(LtcTable::roughnessAt(i, t.size));
    const glm::dvec3 v = viewVector(LtcTable::cosThetaAt(j, t.size));
    const double magnitude =
        hemisphereQuadrature([&](const glm::dvec3& l) { return brdf::specularCos(n, v, l, alpha); }, 1024, 512);
    const double fresnel = hemisphereQuadrature(
        [&](const glm::dvec3& l) {
          return brdf::specularCos(n, v, l, alpha) * brdf::schlickWeight(glm::dot(v, glm::normalize(v + l)));
        },
        1024, 512);
    EXPECT_NEAR(t.magnitudeAt(i, j), magnitude, 2e-3 * magnitude) << "cell i=" << i << " j=" << j;
    EXPECT_NEAR(t.fresnelAt(i, j), fresnel, 2e-4 * magnitude) << "cell i=" << i << " j=" << j;
  }
}

// diffuse_fresnel against the same independent quadrature of (1/pi) cos (1 - v.h)^5. Measured:
// within 0.21% (row 0, where the value is 8e-5) to 0.003% (grazing); the bound is 0.5%.
TEST(LtcFit, DiffuseFresnelMatchesAnIndependentQuadrature) {
  const LtcTable& t = committed();
  for (int j : {0, 20, 40, 63}) {
    const glm::dvec3 v = viewVector(LtcTable::cosThetaAt(j, t.size));
    const double expected = hemisphereQuadrature(
        [&](const glm::dvec3& l) { return l.z / brdf::kPi * brdf::schlickWeight(glm::dot(v, glm::normalize(v + l))); },
        1024, 512);
    EXPECT_NEAR(t.diffuseFresnel[std::size_t(j)], expected, 1e-8 + 5e-3 * expected) << "row " << j;
  }
}

// The sphere table: the cap entirely above the horizon (z >= sqrt(|F|)) is unclipped, its form
// factor F.n = |F| z, so the value is z (1 at z = 1); entirely below (z <= -sqrt(|F|)) it is 0.
TEST(LtcFit, SphereTableClosedFormCells) {
  const LtcTable& t = committed();
  const int n = t.size;
  int above = 0, below = 0;
  for (int iv = 0; iv < n; ++iv)
    for (int iu = 0; iu < n; ++iu) {
      const double z = LtcTable::sphereZAt(iu, n), length = LtcTable::sphereLengthAt(iv, n);
      if (iu == n - 1) {
        EXPECT_NEAR(t.sphereAt(iu, iv), 1.0, 1e-6) << "|F| = " << length;
      }
      if (z >= std::sqrt(length)) {
        EXPECT_NEAR(t.sphereAt(iu, iv), z, 1e-6) << "z = " << z << ", |F| = " << length;
        ++above;
      } else if (z <= -std::sqrt(length)) {
        EXPECT_NEAR(t.sphereAt(iu, iv), 0.0, 1e-6) << "z = " << z << ", |F| = " << length;
        ++below;
      }
    }
  EXPECT_GT(above, n);
  EXPECT_GT(below, n);
}

// A partly clipped cap against Monte Carlo: directions uniform in the cap, (1/pi) cos clamped.
TEST(LtcFit, ClippedCapFormFactorMatchesMonteCarlo) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (const auto& [z, length] : {std::pair{0.0, 0.5}, std::pair{-0.3, 0.3}, std::pair{0.4, 0.9}}) {
    const double cosSigma = std::sqrt(1.0 - length), sinOmega = std::sqrt(1.0 - z * z);
    const glm::dvec3 centre(sinOmega, 0.0, z), x(z, 0.0, -sinOmega), y(0.0, 1.0, 0.0);
    constexpr int kSamples = 400000;
    double sum = 0.0;
    for (int k = 0; k < kSamples; ++k) {
      const double c = 1.0 - uniform(rng) * (1.0 - cosSigma), s = std::sqrt(1.0 - c * c);
      const double phi = 2.0 * brdf::kPi * uniform(rng);
      const glm::dvec3 w = c * centre + s * std::cos(phi) * x + s * std::sin(phi) * y;
      sum += std::max(w.z, 0.0);
    }
    const double solidAngle = 2.0 * brdf::kPi * (1.0 - cosSigma);
    const double monteCarlo = sum / kSamples * solidAngle / brdf::kPi;
    EXPECT_NEAR(clippedCapFormFactor(z, length), monteCarlo, 0.003) << "z = " << z << ", |F| = " << length;
  }
}

// An LTC is a distribution: it integrates to 1 over the sphere, whatever M.
TEST(LtcFit, LtcLobeIntegratesToOne) {
  const glm::dmat3 m(glm::dvec3(0.7, 0.0, 0.2), glm::dvec3(0.0, 0.5, 0.0), glm::dvec3(-0.4, 0.0, 1.0));
  const LtcLobe lobe(m);
  auto sphere = [&](const glm::dvec3& w) { return lobe.evaluate(w) + lobe.evaluate(glm::dvec3(w.x, w.y, -w.z)); };
  EXPECT_NEAR(hemisphereQuadrature(sphere, 1024, 1024), 1.0, 2e-3);
}

// The same seed gives bit-identical tables for any thread count (each view row is one chain with
// its own random streams).
TEST(LtcFit, DeterministicForAnyThreadCount) {
  FitOptions options;
  options.size = 6;
  options.samples = 64;
  options.seed = 9;
  options.threads = 1;
  const LtcTable one = fitTable(options);
  options.threads = 4;
  const LtcTable four = fitTable(options);
  EXPECT_EQ(one.mInv, four.mInv);
  EXPECT_EQ(one.magnitude, four.magnitude);
  EXPECT_EQ(one.error, four.error);
  EXPECT_EQ(one.sphere, four.sphere);
  options.seed = 10;
  EXPECT_NE(fitTable(options).mInv, one.mInv);
}
