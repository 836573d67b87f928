#include "ltc_fit.h"

#include "ltc_lobe.h"
#include "nelder_mead.h"
#include "sphere_form_factor.h"

#include "shading/brdf_model.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>
#include <vector>

namespace rtlab::ltcfit {
namespace {

const glm::dvec3 kNormal(0.0, 0.0, 1.0);

// Random streams of a cell: the moments, the fit's objective, the reported error.
enum Stream { kMomentsStream = 0, kObjectiveStream = 1, kErrorStream = 2 };
// The moments use more samples than the objective: they are computed once per cell.
constexpr int kMomentSampleFactor = 16;

std::uint64_t splitMix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

double unitFromBits(std::uint64_t x) { return double(x >> 11) * 0x1.0p-53; }

// Roberts' R2 sequence (the plastic number's additive recurrence) with a random offset per
// stream: low-discrepancy points in [0,1)^2 for any count.
class R2Sequence {
public:
  explicit R2Sequence(std::uint64_t seed)
      : m_offset1(unitFromBits(splitMix64(seed))), m_offset2(unitFromBits(splitMix64(seed ^ 0x5851f42d4c957f2dull))) {}
  std::pair<double, double> operator()(int k) const {
    constexpr double g = 1.32471795724474602596;
    const double u1 = m_offset1 + double(k) / g, u2 = m_offset2 + double(k) / (g * g);
    return {u1 - std::floor(u1), u2 - std::floor(u2)};
  }

private:
  double m_offset1, m_offset2;
};

// A GGX reflection sample: the direction, or none when v.h <= 0 (a failed sample).
bool sampleReflection(const glm::dvec3& v, double alpha, double u1, double u2, glm::dvec3& l) {
  const glm::dvec3 h = brdf::sampleGgxHalfVector(alpha, u1, u2);
  const double vDotH = glm::dot(v, h);
  if (vDotH <= 0.0) return false;
  l = 2.0 * vDotH * h - v;
  return true;
}

struct LobeSample {
  glm::dvec3 l;
  double lobe; // D V cos / magnitude
  double pdf;  // of GGX reflection sampling
};

// The MIS objective: the GGX samples are fixed for the cell; the LTC samples follow M through the
// same uniform numbers (common random numbers keep the objective smooth for Nelder-Mead).
class Objective {
public:
  Objective(double alpha, double cosTheta, double magnitude, int samples, std::uint64_t seed)
      : m_alpha(alpha), m_v(viewVector(cosTheta)), m_magnitude(magnitude), m_samples(samples) {
    const R2Sequence brdfSeq(seed), ltcSeq(seed ^ 0xa0761d6478bd642full);
    m_uniforms.reserve(std::size_t(samples));
    for (int k = 0; k < samples; ++k) {
      m_uniforms.push_back(ltcSeq(k));
      const auto [u1, u2] = brdfSeq(k);
      glm::dvec3 l;
      if (!sampleReflection(m_v, alpha, u1, u2, l)) continue;
      m_brdfSamples.push_back({l, lobe(l), brdf::ggxReflectionPdf(kNormal, m_v, l, alpha)});
    }
  }

  double lobe(const glm::dvec3& l) const { return brdf::specularCos(kNormal, m_v, l, m_alpha) / m_magnitude; }

  // (1/N) sum over both strategies of |lobe - ltc|^p / (pdf_ggx + pdf_ltc).
  template <class Norm> double estimate(const LtcLobe& ltc, const Norm& norm) const {
    if (!ltc.valid()) return HUGE_VAL;
    double sum = 0.0;
    for (const LobeSample& s : m_brdfSamples) {
      const double g = ltc.evaluate(s.l);
      sum += norm(std::abs(s.lobe - g)) / (s.pdf + g);
    }
    for (const auto& [u1, u2] : m_uniforms) {
      const glm::dvec3 l = ltc.sample(u1, u2);
      const double g = ltc.evaluate(l);
      const double pdf = brdf::ggxReflectionPdf(kNormal, m_v, l, m_alpha);
      if (!(pdf + g > 0.0)) continue;
      sum += norm(std::abs(lobe(l) - g)) / (pdf + g);
    }
    return sum / double(m_samples);
  }

private:
  double m_alpha;
  glm::dvec3 m_v;
  double m_magnitude;
  int m_samples;
  std::vector<LobeSample> m_brdfSamples;
  std::vector<std::pair<double, double>> m_uniforms;
};

std::vector<double> nelderMeadSteps(const std::vector<double>& x) {
  const double scale = std::max(std::abs(x[0]), std::abs(x[1]));
  return {0.05 * std::abs(x[0]) + 1e-6, 0.05 * std::abs(x[1]) + 1e-6, 0.05 * scale + 1e-6};
}

} // namespace

glm::dvec3 viewVector(double cosTheta) {
  return {std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta)), 0.0, cosTheta};
}

glm::dmat3 lobeFrame(const glm::dvec3& averageDir) {
  const glm::dvec3 z = averageDir;
  const glm::dvec3 x(z.z, 0.0, -z.x); // z rotated by -90 degrees about y: in the xz-plane, orthogonal to z
  return glm::dmat3(x, glm::dvec3(0.0, 1.0, 0.0), z);
}

glm::dmat3 viewMatrix(const LtcParams& p, const glm::dvec3& averageDir) {
  // Columns (glm is column-major): M_local = [[m00, 0, m02], [0, m11, 0], [0, 0, 1]] as rows.
  const glm::dmat3 local(glm::dvec3(std::abs(p.m00), 0.0, 0.0), glm::dvec3(0.0, std::abs(p.m11), 0.0),
                         glm::dvec3(p.m02, 0.0, 1.0));
  return lobeFrame(averageDir) * local;
}

std::array<double, 4> packInverse(const glm::dmat3& m) {
  const glm::dmat3 inv = glm::inverse(m);
  const double s = inv[1][1];
  // Element (row r, column c) is inv[c][r].
  return {inv[0][0] / s, inv[2][0] / s, inv[0][2] / s, inv[2][2] / s};
}

glm::dmat3 unpackInverse(const std::array<double, 4>& abcd) {
  glm::dmat3 inv(0.0);
  inv[0][0] = abcd[0];
  inv[2][0] = abcd[1];
  inv[0][2] = abcd[2];
  inv[2][2] = abcd[3];
  inv[1][1] = 1.0;
  return inv;
}

LtcParams paramsFromInverse(const std::array<double, 4>& abcd, const glm::dvec3& averageDir) {
  glm::dmat3 local = glm::transpose(lobeFrame(averageDir)) * glm::inverse(unpackInverse(abcd));
  local /= local[2][2];
  return {local[0][0], local[1][1], local[2][0]};
}

std::uint64_t cellSeed(std::uint64_t seed, int i, int j, int stream) {
  std::uint64_t h = splitMix64(seed);
  h = splitMix64(h ^ std::uint64_t(std::uint32_t(i)));
  h = splitMix64(h ^ (std::uint64_t(std::uint32_t(j)) << 20));
  return splitMix64(h ^ (std::uint64_t(std::uint32_t(stream)) << 40));
}

LobeMoments lobeMoments(double alpha, double cosTheta, int samples, std::uint64_t seed) {
  const glm::dvec3 v = viewVector(cosTheta);
  const R2Sequence seq(seed);
  double magnitude = 0.0, fresnel = 0.0;
  glm::dvec3 direction(0.0);
  for (int k = 0; k < samples; ++k) {
    const auto [u1, u2] = seq(k);
    glm::dvec3 l;
    if (!sampleReflection(v, alpha, u1, u2, l)) continue;
    const double f = brdf::specularCos(kNormal, v, l, alpha);
    if (f <= 0.0) continue;
    const double weight = f / brdf::ggxReflectionPdf(kNormal, v, l, alpha);
    magnitude += weight;
    fresnel += weight * brdf::schlickWeight(glm::dot(v, glm::normalize(v + l)));
    direction += weight * l;
  }
  LobeMoments m;
  m.magnitude = magnitude / double(samples);
  m.fresnel = fresnel / double(samples);
  // Isotropic lobe: its mean lies in the plane of v and n (y = 0 up to noise); exactly +z at
  // normal incidence.
  direction.y = 0.0;
  if (cosTheta >= 1.0) direction = glm::dvec3(0.0, 0.0, 1.0);
  m.averageDir = glm::length(direction) > 0.0 ? glm::normalize(direction) : glm::dvec3(0.0, 0.0, 1.0);
  return m;
}

double lobeL1Error(double alpha, double cosTheta, double magnitude, const glm::dmat3& m, int samples, std::uint64_t seed) {
  const Objective objective(alpha, cosTheta, magnitude, samples, seed);
  return objective.estimate(LtcLobe(m), [](double d) { return d; });
}

LobeMoments cellMoments(int i, int j, int n, int samples, std::uint64_t seed) {
  return lobeMoments(brdf::alphaFromRoughness(LtcTable::roughnessAt(i, n)), LtcTable::cosThetaAt(j, n),
                     kMomentSampleFactor * samples, cellSeed(seed, i, j, kMomentsStream));
}

double ltcL1Difference(const glm::dmat3& a, const glm::dmat3& b, int samples, std::uint64_t seed) {
  const LtcLobe lobeA(a), lobeB(b);
  const R2Sequence seqA(seed), seqB(seed ^ 0xa0761d6478bd642full);
  double sum = 0.0;
  for (int k = 0; k < samples; ++k)
    for (const auto& [lobe, seq] : {std::pair{&lobeA, &seqA}, std::pair{&lobeB, &seqB}}) {
      const auto [u1, u2] = (*seq)(k);
      const glm::dvec3 l = lobe->sample(u1, u2);
      const double pa = lobeA.evaluate(l), pb = lobeB.evaluate(l);
      if (pa + pb > 0.0) sum += std::abs(pa - pb) / (pa + pb);
    }
  return sum / double(samples);
}

CellFit fitCell(int i, int j, int n, const LtcParams& start, int samples, std::uint64_t seed) {
  const double alpha = brdf::alphaFromRoughness(LtcTable::roughnessAt(i, n));
  const double cosTheta = LtcTable::cosThetaAt(j, n);
  CellFit fit;
  fit.moments = cellMoments(i, j, n, samples, seed);
  const glm::dvec3 averageDir = fit.moments.averageDir;
  const Objective objective(alpha, cosTheta, fit.moments.magnitude, samples, cellSeed(seed, i, j, kObjectiveStream));
  auto cubed = [](double d) { return d * d * d; };
  auto f = [&](const std::vector<double>& x) {
    return objective.estimate(LtcLobe(viewMatrix({x[0], x[1], x[2]}, averageDir)), cubed);
  };
  std::vector<double> x = {start.m00, start.m11, start.m02};
  // Two runs, the second restarted from the first's best point with a fresh simplex: a simplex
  // collapsed along a valley otherwise stops early.
  for (int run = 0; run < 2; ++run) {
    const NelderMeadResult r = nelderMead(f, x, nelderMeadSteps(x), 1e-7, 400);
    x = r.x;
    fit.evaluations += r.evaluations;
  }
  fit.params = {std::abs(x[0]), std::abs(x[1]), x[2]};
  const glm::dmat3 m = viewMatrix(fit.params, averageDir);
  fit.mInv = packInverse(m);
  fit.error = lobeL1Error(alpha, cosTheta, fit.moments.magnitude, m, samples, cellSeed(seed, i, j, kErrorStream));
  return fit;
}

double diffuseFresnel(double cosTheta) {
  // Cosine-distributed directions on a K x K midpoint grid: (1/pi) integral of cos g = E[g].
  constexpr int kGrid = 256;
  const glm::dvec3 v = viewVector(cosTheta);
  double sum = 0.0;
  for (int a = 0; a < kGrid; ++a)
    for (int b = 0; b < kGrid; ++b) {
      const glm::dvec3 l = sampleCosine((a + 0.5) / kGrid, (b + 0.5) / kGrid);
      sum += brdf::schlickWeight(glm::dot(v, glm::normalize(v + l)));
    }
  return sum / double(kGrid * kGrid);
}

LtcTable fitTable(const FitOptions& options, const std::function<void(int)>& progress) {
  const int n = options.size;
  LtcTable table = LtcTable::withSize(n);
  table.seed = options.seed;
  table.samples = options.samples;
  table.threads = options.threads;
  // One chain per view row: roughness from 1 down, each cell warm-started from the rougher one.
  // Rows are independent, so any thread count gives the same table.
  std::atomic<int> nextRow{0};
  auto worker = [&] {
    for (int j = nextRow.fetch_add(1); j < n; j = nextRow.fetch_add(1)) {
      LtcParams params; // identity in the lobe's frame: the cosine about the average direction
      for (int i = n - 1; i >= 0; --i) {
        const CellFit fit = fitCell(i, j, n, params, options.samples, options.seed);
        params = fit.params;
        const std::size_t k = std::size_t(table.cell(i, j));
        for (int c = 0; c < 4; ++c) table.mInv[4 * k + std::size_t(c)] = float(fit.mInv[std::size_t(c)]);
        table.magnitude[k] = float(fit.moments.magnitude);
        table.fresnel[k] = float(fit.moments.fresnel);
        table.error[k] = float(fit.error);
        if (progress) progress(1);
      }
      table.diffuseFresnel[std::size_t(j)] = float(diffuseFresnel(LtcTable::cosThetaAt(j, n)));
    }
  };
  std::vector<std::thread> threads;
  for (int t = 1; t < options.threads; ++t) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
  for (int iv = 0; iv < n; ++iv)
    for (int iu = 0; iu < n; ++iu)
      table.sphere[std::size_t(table.cell(iu, iv))] =
          float(sphereTableValue(LtcTable::sphereZAt(iu, n), LtcTable::sphereLengthAt(iv, n)));
  return table;
}

} // namespace rtlab::ltcfit
