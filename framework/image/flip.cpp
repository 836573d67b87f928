// LDR-FLIP: P. Andersson, J. Nilsson, T. Akenine-Möller, M. Oskarsson, K. Åström, M. D. Fairchild,
// "FLIP: A Difference Evaluator for Alternating Images", Proc. ACM Comput. Graph. Interact. Tech.
// 3(2), article 15 (HPG 2020). Implemented from the paper's description:
//
//  colour pipeline (Section 4.1)
//   1. linear RGB -> XYZ -> YyCxCz (Johnson & Fairchild's linearised L*a*b*: Yy = 116 Y/Yn - 16,
//      Cx = 500 (X/Xn - Y/Yn), Cz = 200 (Y/Yn - Z/Zn); white = XYZ of RGB (1,1,1));
//   2. each channel convolved with its contrast sensitivity function, a sum of Gaussians
//      s(x) = sum_i a_i sqrt(pi / b_i) exp(-pi^2 |x|^2 / b_i), x in degrees, normalised to sum 1:
//      achromatic a1 = 1, b1 = 0.0047; red-green a1 = 1, b1 = 0.0053; blue-yellow a1 = 34.1,
//      b1 = 0.04, a2 = 13.5, b2 = 0.025; radius ceil(3 sqrt(max b / (2 pi^2)) ppd) pixels;
//   3. back to linear RGB, clamped to [0,1]; to CIE L*a*b*; Hunt adjustment a *= 0.01 L,
//      b *= 0.01 L;
//   4. HyAB distance |dL| + ||(da, db)||, raised to qc = 0.7 and redistributed to [0,1]: values
//      below pc * cmax (pc = 0.4) map linearly to [0, pt] (pt = 0.95), the rest to [pt, 1], where
//      cmax = HyAB(Hunt-adjusted green, Hunt-adjusted blue)^qc, the largest difference of the gamut;
//  feature pipeline (Section 4.2)
//   5. on the achromatic channel Y/Yn of the unfiltered images: edges (first derivative of a
//      Gaussian) and points (second derivative), with sigma = w/2 degrees, w = 0.082, radius
//      ceil(3 sigma) pixels, positive weights normalised to sum 1 and negative ones to sum -1,
//      each in x and y;
//   6. dE_f = ( max(| |edge_A| - |edge_B| |, | |point_A| - |point_B| |) / sqrt 2 )^qf, qf = 0.5;
//  combination (Section 4.3): dE = dE_c^(1 - dE_f).
// Borders replicate the edge pixel. Every kernel above is a sum of separable terms and is applied
// as two 1-D passes. docs/metrics.md describes the input rule and the viewing conditions.
#include "image/metrics.h"
#include "image/metrics_internal.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace rtlab {
namespace detail {
namespace {

using Vec3 = std::array<float, 3>;
using Plane = std::vector<float>;
constexpr double kPi = std::numbers::pi;

// sRGB primaries, D65 (IEC 61966-2-1).
constexpr double kRgbToXyz[3][3] = {{0.4124564, 0.3575761, 0.1804375},
                                    {0.2126729, 0.7151522, 0.0721750},
                                    {0.0193339, 0.1191920, 0.9503041}};
constexpr double kXyzToRgb[3][3] = {{3.2404542, -1.5371385, -0.4985314},
                                    {-0.9692660, 1.8760108, 0.0415560},
                                    {0.0556434, -0.2040259, 1.0572252}};
// Reference white: XYZ of linear RGB (1, 1, 1).
constexpr double kWhite[3] = {0.4124564 + 0.3575761 + 0.1804375, 0.2126729 + 0.7151522 + 0.0721750,
                              0.0193339 + 0.1191920 + 0.9503041};

// f(i) for i in [0, n), in parallel.
template <class F> void forEachPixel(std::size_t n, const F& f) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i < r.end(); ++i) f(i);
  });
}

Vec3 mul(const double m[3][3], const Vec3& v) {
  Vec3 r;
  for (int i = 0; i < 3; ++i) r[i] = float(m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2]);
  return r;
}

Vec3 linearRgbToYcxcz(const Vec3& rgb) {
  const Vec3 xyz = mul(kRgbToXyz, rgb);
  const double x = xyz[0] / kWhite[0], y = xyz[1] / kWhite[1], z = xyz[2] / kWhite[2];
  return {float(116.0 * y - 16.0), float(500.0 * (x - y)), float(200.0 * (y - z))};
}

Vec3 ycxczToLinearRgb(const Vec3& c) {
  const double y = (c[0] + 16.0) / 116.0;
  const double x = y + c[1] / 500.0, z = y - c[2] / 200.0;
  return mul(kXyzToRgb, Vec3{float(x * kWhite[0]), float(y * kWhite[1]), float(z * kWhite[2])});
}

// CIE 1976 L*a*b* of linear RGB, then the Hunt adjustment (chroma scaled by 0.01 L*).
Vec3 huntAdjustedLab(const Vec3& rgb) {
  const Vec3 xyz = mul(kRgbToXyz, rgb);
  constexpr double d = 6.0 / 29.0;
  auto f = [](double t) { return t > d * d * d ? double(std::cbrt(float(t))) : t / (3.0 * d * d) + 4.0 / 29.0; };
  const double fx = f(xyz[0] / kWhite[0]), fy = f(xyz[1] / kWhite[1]), fz = f(xyz[2] / kWhite[2]);
  const double L = 116.0 * fy - 16.0, a = 500.0 * (fx - fy), b = 200.0 * (fy - fz);
  return {float(L), float(0.01 * L * a), float(0.01 * L * b)};
}

float hyab(const Vec3& p, const Vec3& q) {
  const float da = p[1] - q[1], db = p[2] - q[2];
  return std::abs(p[0] - q[0]) + std::sqrt(da * da + db * db);
}

// Correlates a plane with kx along rows, then ky along columns; borders replicate the edge pixel.
Plane separable(const Plane& src, int w, int h, const std::vector<float>& kx, const std::vector<float>& ky) {
  const int rx = int(kx.size() / 2), ry = int(ky.size() / 2);
  Plane tmp(src.size()), dst(src.size());
  tbb::parallel_for(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
    std::vector<float> padded(std::size_t(w) + 2 * rx); // the row with replicated borders
    for (int y = rows.begin(); y < rows.end(); ++y) {
      const float* in = &src[std::size_t(y) * w];
      for (int x = -rx; x < w + rx; ++x) padded[x + rx] = in[std::clamp(x, 0, w - 1)];
      float* out = &tmp[std::size_t(y) * w];
      std::fill(out, out + w, 0.0f);
      for (int i = 0; i <= 2 * rx; ++i) { // taps outside, pixels inside: vectorisable
        const float k = kx[i];
        const float* p = &padded[i];
        for (int x = 0; x < w; ++x) out[x] += k * p[x];
      }
    }
  });
  tbb::parallel_for(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) {
      float* out = &dst[std::size_t(y) * w];
      std::fill(out, out + w, 0.0f);
      for (int i = -ry; i <= ry; ++i) {
        const float* in = &tmp[std::size_t(std::clamp(y + i, 0, h - 1)) * w];
        const float k = ky[i + ry];
        for (int x = 0; x < w; ++x) out[x] += k * in[x];
      }
    }
  });
  return dst;
}

// One channel's contrast sensitivity filter: separable terms (1-D kernel, weight of the term).
struct CsfFilter {
  std::vector<std::pair<std::vector<float>, float>> terms;
};

CsfFilter csfFilter(double a1, double b1, double a2, double b2, double ppd) {
  constexpr double kMaxB = 0.04; // the largest b over all channels sets one radius for all
  const int r = int(std::ceil(3.0 * std::sqrt(kMaxB / (2.0 * kPi * kPi)) * ppd));
  const double dx = 1.0 / ppd; // degrees per pixel
  CsfFilter f;
  double total = 0.0;
  for (auto [a, b] : {std::pair{a1, b1}, std::pair{a2, b2}}) {
    if (a == 0.0) continue;
    std::vector<float> k(2 * r + 1);
    double sum = 0.0;
    for (int i = -r; i <= r; ++i) sum += k[i + r] = float(std::exp(-kPi * kPi * (i * dx) * (i * dx) / b));
    const double weight = a * std::sqrt(kPi / b);
    total += weight * sum * sum; // the 2-D term's sum
    f.terms.push_back({k, float(weight)});
  }
  for (auto& t : f.terms) t.second = float(t.second / total);
  return f;
}

Plane applyCsf(const Plane& src, int w, int h, const CsfFilter& f) {
  Plane out(src.size(), 0.0f);
  for (const auto& [k, weight] : f.terms) {
    const Plane part = separable(src, w, h, k, k);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] += weight * part[i];
  }
  return out;
}

// 1-D profiles of the feature detectors (Section 4.2): derivative profile along the feature
// direction (positive weights sum to 1, negative to -1) and the Gaussian across it (sums to 1).
struct FeatureKernels {
  std::vector<float> edge, point, gauss;
};

FeatureKernels featureKernels(double ppd) {
  constexpr double kW = 0.082; // peak-to-trough width of the edge detector, degrees
  const double sd = 0.5 * kW * ppd;
  const int r = int(std::ceil(3.0 * sd));
  std::vector<double> g(2 * r + 1), e(2 * r + 1), p(2 * r + 1);
  double gSum = 0.0;
  for (int i = -r; i <= r; ++i) {
    g[i + r] = std::exp(-(i * i) / (2.0 * sd * sd));
    e[i + r] = -i * g[i + r];
    p[i + r] = (i * i / (sd * sd) - 1.0) * g[i + r];
    gSum += g[i + r];
  }
  auto normalise = [](const std::vector<double>& v) {
    double pos = 0.0, neg = 0.0;
    for (double x : v) (x > 0 ? pos : neg) += x;
    std::vector<float> out(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) out[i] = float(v[i] > 0 ? v[i] / pos : (v[i] < 0 ? v[i] / -neg : 0.0));
    return out;
  };
  FeatureKernels k;
  k.edge = normalise(e);
  k.point = normalise(p);
  k.gauss.resize(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) k.gauss[i] = float(g[i] / gSum);
  return k;
}

// What one image contributes: Hunt-adjusted L*a*b* of the CSF-filtered image, and the magnitudes
// of its edge and point responses.
struct Prepared {
  std::vector<Vec3> lab;
  Plane edges, points;
};

Prepared prepare(const std::vector<float>& rgb, int w, int h, double ppd) {
  const std::size_t n = std::size_t(w) * h;
  std::array<Plane, 3> opp;
  for (auto& p : opp) p.resize(n);
  Plane achromatic(n);
  forEachPixel(n, [&](std::size_t i) {
    const Vec3 c = linearRgbToYcxcz({rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]});
    for (int k = 0; k < 3; ++k) opp[k][i] = c[k];
    achromatic[i] = (c[0] + 16.0f) / 116.0f; // Y / Yn
  });
  static thread_local double cachedPpd = -1.0;
  static thread_local std::array<CsfFilter, 3> csf;
  if (cachedPpd != ppd) {
    csf = {csfFilter(1.0, 0.0047, 0.0, 1e-5, ppd), csfFilter(1.0, 0.0053, 0.0, 1e-5, ppd),
           csfFilter(34.1, 0.04, 13.5, 0.025, ppd)};
    cachedPpd = ppd;
  }
  std::array<Plane, 3> filtered;
  for (int k = 0; k < 3; ++k) filtered[k] = applyCsf(opp[k], w, h, csf[k]);

  Prepared out;
  out.lab.resize(n);
  forEachPixel(n, [&](std::size_t i) {
    Vec3 c = ycxczToLinearRgb({filtered[0][i], filtered[1][i], filtered[2][i]});
    for (float& v : c) v = std::clamp(v, 0.0f, 1.0f);
    out.lab[i] = huntAdjustedLab(c);
  });

  const FeatureKernels fk = featureKernels(ppd);
  const Plane ex = separable(achromatic, w, h, fk.edge, fk.gauss), ey = separable(achromatic, w, h, fk.gauss, fk.edge);
  const Plane qx = separable(achromatic, w, h, fk.point, fk.gauss), qy = separable(achromatic, w, h, fk.gauss, fk.point);
  out.edges.resize(n);
  out.points.resize(n);
  forEachPixel(n, [&](std::size_t i) {
    out.edges[i] = std::sqrt(ex[i] * ex[i] + ey[i] * ey[i]);
    out.points[i] = std::sqrt(qx[i] * qx[i] + qy[i] * qy[i]);
  });
  return out;
}

float srgbToLinear(float v) {
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

// FLIP's input: linear RGB in [0,1] (MetricsOptions).
std::vector<float> flipInput(const std::vector<float>& pixels, int channels, bool display) {
  const std::size_t n = pixels.size() / channels;
  std::vector<float> rgb(3 * n);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      const float v = std::clamp(pixels[i * channels + (channels == 3 ? k : 0)], 0.0f, 1.0f);
      rgb[3 * i + k] = (display || channels == 1) ? srgbToLinear(v) : v;
    }
  return rgb;
}

} // namespace

std::vector<float> ldrFlip(const std::vector<float>& reference, const std::vector<float>& test, int width, int height,
                           double ppd) {
  constexpr float kQc = 0.7f, kQf = 0.5f, kPc = 0.4f, kPt = 0.95f;
  static const float cmax =
      std::pow(hyab(huntAdjustedLab({0.0f, 1.0f, 0.0f}), huntAdjustedLab({0.0f, 0.0f, 1.0f})), kQc);
  Prepared r, t;
  tbb::parallel_invoke([&] { r = prepare(reference, width, height, ppd); },
                       [&] { t = prepare(test, width, height, ppd); });
  const std::size_t n = std::size_t(width) * height;
  std::vector<float> error(n);
  const float pcCmax = kPc * cmax;
  forEachPixel(n, [&](std::size_t i) {
    const float dc = std::pow(hyab(r.lab[i], t.lab[i]), kQc);
    const float colour = dc < pcCmax ? (kPt / pcCmax) * dc : kPt + (dc - pcCmax) / (cmax - pcCmax) * (1.0f - kPt);
    const float feature = std::pow(
        std::max(std::abs(r.edges[i] - t.edges[i]), std::abs(r.points[i] - t.points[i])) / std::numbers::sqrt2_v<float>,
        kQf);
    error[i] = std::clamp(std::pow(colour, 1.0f - feature), 0.0f, 1.0f);
  });
  return error;
}

std::vector<float> flipMap(const PreparedPair& pair, const MetricsOptions& options) {
  return ldrFlip(flipInput(pair.a, pair.channels, options.displayEncoded),
                 flipInput(pair.b, pair.channels, options.displayEncoded), pair.width, pair.height,
                 pixelsPerDegree(options));
}

} // namespace detail

Image flipErrorImage(const Image& a, const Image& b, const MetricsOptions& options) {
  const detail::PreparedPair pair = detail::preparePair(a, b);
  const std::vector<float> map = detail::flipMap(pair, options);
  Image out(pair.width, pair.height, 1);
  out.mask.assign(pair.valid.size(), 0.0f);
  for (std::size_t i = 0; i < map.size(); ++i)
    if (pair.valid[i]) {
      out.pixels[i] = map[i];
      out.mask[i] = 1.0f;
    }
  return out;
}

} // namespace rtlab
