// SSIM: Z. Wang, A. C. Bovik, H. R. Sheikh, E. P. Simoncelli, "Image Quality Assessment: From
// Error Visibility to Structural Similarity", IEEE TIP 13(4), 2004. Section III-C: local statistics
// under an 11x11 circular-symmetric Gaussian window (sigma 1.5, weights summing to 1), eq. (13)
// with C1 = (K1 L)^2, C2 = (K2 L)^2, K1 = 0.01, K2 = 0.03, and the mean over the image (MSSIM,
// eq. (17)). L, the dynamic range, is 1 (the peak of PSNR).
//
// Masks: a window counts only valid pixels. Each window's weights are w(d) * valid(p + d),
// renormalised by their sum, so the means, variances and covariance are those of the valid pixels
// under the Gaussian. Windows cut by the image border are renormalised the same way (Wang et al.'s
// own code skips the 5-pixel border instead). The mean runs over valid centre pixels.
#include "image/metrics_internal.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rtlab::detail {
namespace {

constexpr int kRadius = 5;       // 11x11 window
constexpr double kSigma = 1.5;
constexpr double kC1 = 0.01 * 0.01; // (K1 L)^2, L = 1
constexpr double kC2 = 0.03 * 0.03; // (K2 L)^2

// Weighted sums of a window: weight, x, y, x^2, y^2, xy.
struct Moments {
  double w = 0, x = 0, y = 0, xx = 0, yy = 0, xy = 0;
  void add(double g, const Moments& o) {
    w += g * o.w;
    x += g * o.x;
    y += g * o.y;
    xx += g * o.xx;
    yy += g * o.yy;
    xy += g * o.xy;
  }
};

std::array<double, 2 * kRadius + 1> gaussianWeights() {
  std::array<double, 2 * kRadius + 1> g{};
  double sum = 0.0;
  for (int d = -kRadius; d <= kRadius; ++d) sum += g[d + kRadius] = std::exp(-(d * d) / (2.0 * kSigma * kSigma));
  for (double& v : g) v /= sum; // the 2-D window g(dx) g(dy) then sums to 1
  return g;
}

} // namespace

double meanSsim(const std::vector<float>& x, const std::vector<float>& y, const std::vector<std::uint8_t>& valid,
                int width, int height, std::vector<float>* map) {
  static const auto g = gaussianWeights();
  if (map) map->assign(std::size_t(width) * height, 0.0f);

  // Horizontal sums of rows, kept in a ring of 2 * kRadius + 1 rows for the vertical pass.
  constexpr int kRing = 2 * kRadius + 1;
  std::vector<Moments> ring(std::size_t(kRing) * width);
  int rowsDone = 0; // rows [0, rowsDone) have been filtered horizontally
  auto filterRow = [&](int row) {
    Moments* out = &ring[std::size_t(row % kRing) * width];
    const std::size_t base = std::size_t(row) * width;
    for (int px = 0; px < width; ++px) {
      Moments s;
      const int lo = std::max(0, px - kRadius), hi = std::min(width - 1, px + kRadius);
      for (int q = lo; q <= hi; ++q) {
        const std::size_t i = base + q;
        if (!valid[i]) continue;
        const double gw = g[q - px + kRadius], xv = x[i], yv = y[i];
        s.w += gw;
        s.x += gw * xv;
        s.y += gw * yv;
        s.xx += gw * xv * xv;
        s.yy += gw * yv * yv;
        s.xy += gw * xv * yv;
      }
      out[px] = s;
    }
  };

  double sum = 0.0;
  std::size_t count = 0;
  for (int py = 0; py < height; ++py) {
    const int lo = std::max(0, py - kRadius), hi = std::min(height - 1, py + kRadius);
    while (rowsDone <= hi) filterRow(rowsDone++);
    for (int px = 0; px < width; ++px) {
      const std::size_t i = std::size_t(py) * width + px;
      if (!valid[i]) continue;
      Moments s;
      for (int q = lo; q <= hi; ++q) s.add(g[q - py + kRadius], ring[std::size_t(q % kRing) * width + px]);
      // s.w >= g(0)^2 > 0: the centre pixel is valid.
      const double mx = s.x / s.w, my = s.y / s.w;
      // No clamping of rounding-level negative variances: with x == y the numerator and the
      // denominator are then the same expression, and SSIM is exactly 1.
      const double vx = s.xx / s.w - mx * mx, vy = s.yy / s.w - my * my;
      const double cxy = s.xy / s.w - mx * my;
      const double ssim = ((2.0 * mx * my + kC1) * (2.0 * cxy + kC2)) / ((mx * mx + my * my + kC1) * (vx + vy + kC2));
      sum += ssim;
      ++count;
      if (map) (*map)[i] = float(ssim);
    }
  }
  return count ? sum / double(count) : 1.0;
}

} // namespace rtlab::detail
