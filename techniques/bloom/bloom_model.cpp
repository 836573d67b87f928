#include "techniques/bloom/bloom_model.h"

#include "util/error.h"

#include <algorithm>
#include <cmath>
#include <thread>

namespace rtlab::bloom {

Definition definitionFrom(const ParamSet& p) {
  Definition d;
  d.threshold = p.getFloat("bloom.threshold");
  d.knee = p.getFloat("bloom.knee");
  d.intensity = p.getFloat("bloom.intensity");
  d.sigma = p.getFloat("bloom.sigma");
  d.octaves = p.getInt("bloom.octaves");
  d.hardCut = p.getBool("bloom.hard_cut");
  return d;
}

float brightWeight(float luma, const Definition& d) {
  const float t = d.threshold;
  if (d.hardCut) return luma > t ? 1.0f : 0.0f;
  const float k = d.knee * t;
  const float q = std::clamp(luma - t + k, 0.0f, 2.0f * k);
  const float w = std::max(q * q / (4.0f * k + 1e-5f), luma - t) / std::max(luma, 1e-5f);
  return std::max(w, 0.0f);
}

double octaveSigma(const Definition& d, int k) { return double(d.sigma) * std::ldexp(1.0, k); }

int gaussianRadius(double sigma) { return int(std::ceil(4.0 * sigma)); }

double gaussianNormalisation(double sigma, int radius) {
  double sum = 1.0;
  for (int i = 1; i <= radius; ++i) sum += 2.0 * std::exp(-double(i) * i / (2.0 * sigma * sigma));
  return 1.0 / sum;
}

Image brightPass(const Image& color, const Definition& d, InputCounts* counts) {
  Image out(color.width, color.height, 3);
  for (std::size_t p = 0; p < color.pixelCount(); ++p) {
    float c[3];
    bool finite = true;
    for (int ch = 0; ch < 3; ++ch) {
      c[ch] = color.pixels[p * std::size_t(color.channels) + std::size_t(std::min(ch, color.channels - 1))];
      finite = finite && std::isfinite(c[ch]);
    }
    if (!finite) {
      if (counts) ++counts->nonFinite;
      continue; // stays 0
    }
    const float w = brightWeight(kLumaR * c[0] + kLumaG * c[1] + kLumaB * c[2], d);
    for (int ch = 0; ch < 3; ++ch) out.pixels[p * 3 + std::size_t(ch)] = c[ch] * w;
  }
  return out;
}

namespace {

// Runs body(begin, end) over [0, count) split into contiguous ranges, one per thread.
template <class Body>
void parallelRanges(int count, unsigned threads, const Body& body) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  threads = std::min<unsigned>(threads, unsigned(std::max(count, 1)));
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t)
    pool.emplace_back([&, t] { body(int(count * std::int64_t(t) / threads), int(count * std::int64_t(t + 1) / threads)); });
  body(0, int(count / std::int64_t(threads)));
  for (auto& th : pool) th.join();
}

// The truncated, renormalised 1D kernel of width sigma: w[i] for i = 0..R (symmetric).
std::vector<double> kernel(double sigma) {
  const int radius = gaussianRadius(sigma);
  const double norm = gaussianNormalisation(sigma, radius);
  std::vector<double> w(std::size_t(radius) + 1);
  for (int i = 0; i <= radius; ++i) w[std::size_t(i)] = norm * std::exp(-double(i) * i / (2.0 * sigma * sigma));
  return w;
}

} // namespace

Image convolve(const Image& bright, const Definition& d, unsigned threads, const std::atomic<bool>* cancel) {
  const int width = bright.width, height = bright.height;
  auto stop = [cancel] { return cancel && cancel->load(std::memory_order_relaxed); };
  auto checkCancel = [&] {
    if (stop()) throw Error(ExitCode::Interrupted, "bloom reference cancelled");
  };
  const std::size_t n = bright.pixelCount() * 3;
  std::vector<double> sum(n, 0.0), rows(n);
  for (int k = 0; k < d.octaves; ++k) {
    const std::vector<double> w = kernel(octaveSigma(d, k));
    const int radius = int(w.size()) - 1;
    // Rows: taps outside the frame read black, so they are left out (not renormalised away).
    parallelRanges(height, threads, [&](int y0, int y1) {
      for (int y = y0; y < y1 && !stop(); ++y)
        for (int x = 0; x < width; ++x) {
          double acc[3] = {0, 0, 0};
          const int lo = std::max(-radius, -x), hi = std::min(radius, width - 1 - x);
          for (int i = lo; i <= hi; ++i) {
            const float* s = &bright.pixels[(std::size_t(y) * width + std::size_t(x + i)) * 3];
            const double wi = w[std::size_t(std::abs(i))];
            acc[0] += wi * s[0];
            acc[1] += wi * s[1];
            acc[2] += wi * s[2];
          }
          double* o = &rows[(std::size_t(y) * width + std::size_t(x)) * 3];
          o[0] = acc[0];
          o[1] = acc[1];
          o[2] = acc[2];
        }
    });
    checkCancel();
    // Columns, accumulated row by row so the inner loop runs along memory.
    parallelRanges(height, threads, [&](int y0, int y1) {
      for (int y = y0; y < y1 && !stop(); ++y) {
        const int lo = std::max(-radius, -y), hi = std::min(radius, height - 1 - y);
        double* o = &sum[std::size_t(y) * width * 3];
        for (int i = lo; i <= hi; ++i) {
          const double wi = w[std::size_t(std::abs(i))];
          const double* s = &rows[std::size_t(y + i) * width * 3];
          for (std::size_t j = 0; j < std::size_t(width) * 3; ++j) o[j] += wi * s[j];
        }
      }
    });
    checkCancel();
  }
  Image out(width, height, 3);
  const double scale = double(d.intensity) / double(std::max(d.octaves, 1));
  for (std::size_t i = 0; i < n; ++i) out.pixels[i] = float(scale * sum[i]);
  out.mask.assign(bright.pixelCount(), 1.0f);
  return out;
}

double mipLevelSigma(int level) {
  // Level 0 is the bright pass itself: one pixel, whose box has the variance 1/12 per axis.
  if (level == 0) return std::sqrt(1.0 / 12.0);
  return std::sqrt(1.5 * (std::ldexp(1.0, 2 * level) - 1.0));
}

int maxMipLevels(int width, int height) {
  int levels = 0;
  while ((std::min(width, height) >> (levels + 1)) >= 1) ++levels;
  return levels;
}

namespace {

// The inner product of two normalised isotropic 2D Gaussians: 1 / (2 pi (a^2 + b^2)).
double gaussianDot(double a, double b) { return 1.0 / (2.0 * M_PI * (a * a + b * b)); }

// Solves A x = b (n x n, row-major) by Gaussian elimination with partial pivoting.
std::vector<double> solve(std::vector<double> a, std::vector<double> b) {
  const std::size_t n = b.size();
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (std::abs(a[r * n + c]) > std::abs(a[pivot * n + c])) pivot = r;
    for (std::size_t k = 0; k < n; ++k) std::swap(a[c * n + k], a[pivot * n + k]);
    std::swap(b[c], b[pivot]);
    for (std::size_t r = c + 1; r < n; ++r) {
      const double f = a[r * n + c] / a[c * n + c];
      for (std::size_t k = c; k < n; ++k) a[r * n + k] -= f * a[c * n + k];
      b[r] -= f * b[c];
    }
  }
  std::vector<double> x(n);
  for (std::size_t r = n; r-- > 0;) {
    double v = b[r];
    for (std::size_t k = r + 1; k < n; ++k) v -= a[r * n + k] * x[k];
    x[r] = v / a[r * n + r];
  }
  return x;
}

} // namespace

MipPlan planMipChain(const Definition& d, int width, int height) {
  MipPlan plan;
  const int deepest = maxMipLevels(width, height);
  // The levels the widest octave needs: the first whose width reaches it.
  const double widest = octaveSigma(d, d.octaves - 1);
  while (plan.levels < deepest && mipLevelSigma(plan.levels) < widest) ++plan.levels;
  for (int k = 0; k < d.octaves; ++k)
    if (octaveSigma(d, k) > mipLevelSigma(plan.levels)) ++plan.cappedOctaves;
  // Least squares in 2D: the weights a_j >= 0, sum 1, of the levels' PSFs (each modelled as a
  // Gaussian of width mipLevelSigma(j)) closest in L2 to the declared mean of Gaussians. Solved on
  // the set of free levels with a Lagrange multiplier for the sum; a level whose weight comes out
  // negative is fixed at 0 (the most negative first) and the rest solved again.
  const int m = plan.levels + 1;
  std::vector<bool> free(std::size_t(m), true);
  std::vector<double> weights(std::size_t(m), 0.0);
  for (int round = 0; round < m; ++round) {
    std::vector<int> index;
    for (int j = 0; j < m; ++j)
      if (free[std::size_t(j)]) index.push_back(j);
    const std::size_t n = index.size() + 1;
    std::vector<double> a(n * n, 0.0), b(n, 0.0);
    for (std::size_t r = 0; r < index.size(); ++r) {
      const double sr = mipLevelSigma(index[r]);
      for (std::size_t c = 0; c < index.size(); ++c) a[r * n + c] = gaussianDot(sr, mipLevelSigma(index[c]));
      a[r * n + n - 1] = 1.0;
      a[(n - 1) * n + r] = 1.0;
      for (int k = 0; k < d.octaves; ++k) b[r] += gaussianDot(sr, octaveSigma(d, k)) / d.octaves;
    }
    b[n - 1] = 1.0;
    const std::vector<double> x = solve(a, b);
    int worst = -1;
    for (std::size_t r = 0; r < index.size(); ++r)
      if (x[r] < 0.0 && (worst < 0 || x[r] < x[std::size_t(worst)])) worst = int(r);
    if (worst < 0) {
      std::fill(weights.begin(), weights.end(), 0.0);
      for (std::size_t r = 0; r < index.size(); ++r) weights[std::size_t(index[r])] = x[r];
      break;
    }
    free[std::size_t(index[std::size_t(worst)])] = false;
  }
  plan.weights.assign(weights.begin(), weights.end());
  return plan;
}

} // namespace rtlab::bloom
