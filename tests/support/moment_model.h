// A CPU model of the moment techniques' arithmetic (vssm, msm), in double and in float, to find
// where the shaders' 32-bit floats break (techniques/vssm/README.md and techniques/msm/README.md,
// "Precision"; docs/performance.md, "Issue 19: moment precision"). It follows, step for step:
//   - shaders/shadow/moments.frag: the moments of a normalized depth z, with msm's optimized
//     transform (Peters & Klein 2015, section 4.3), and the storage format's rounding;
//   - shaders/shadow/sat.comp: round((moment - offset) * scale) per texel, summed in unsigned
//     32-bit integers that wrap, and boxMoments' four-corner difference (which wraps the same way);
//   - shaders/shadow/common/moments.glsl: the box mean, Chebyshev's bound, the blocker estimate, the
//     bleeding reduction, the inverse optimized transform and the Hamburger 4MSM bound.
// Every function is a template on the arithmetic type T: `float` emulates the shader's order of
// operations in IEEE single precision (no fused multiply-add: x86-64's SSE arithmetic), `double`
// is the fp64 model. No GL.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace rtlab::moment_model {

template <class T> using Vec4 = std::array<T, 4>;

// Storage formats of the moment map: vssm.format (rg32f, rg16f) and msm.format (rgba32f,
// rgba16_optimized = RGBA16 normalized integers, rgba16f_optimized = RGBA16F half floats).
enum class Storage { Float32, Half16, Unorm16 };

// Nearest half float (round half to even) of a finite float in the half's normal or subnormal
// range, as a float: 11 significant bits, subnormal step 2^-24.
inline float roundToHalf(float v) {
  if (v == 0.0f || !std::isfinite(v)) return v;
  int exponent = 0;
  std::frexp(v, &exponent);                  // |v| in [2^(e-1), 2^e)
  const int e = std::max(exponent - 1, -14); // the half's exponent, clamped to its subnormals
  const double step = std::ldexp(1.0, e - 10);
  return float(std::nearbyint(double(v) / step) * step);
}

// The value a texel of the given storage holds for a shader output v (GL's conversions: float
// to half rounds to nearest; to a normalized 16-bit integer clamps to [0,1] and rounds).
inline float store(double v, Storage storage) {
  switch (storage) {
  case Storage::Float32: return float(v);
  case Storage::Half16: return roundToHalf(float(v));
  case Storage::Unorm16: return float(std::nearbyint(std::clamp(v, 0.0, 1.0) * 65535.0) / 65535.0);
  }
  return float(v);
}

// Peters & Klein 2015, section 4.3 (shaders/shadow/moments.frag's kOptimize, column-major, and the
// offset of the first moment), and its inverse (moments.glsl's kRestoreOptimized).
constexpr double kOptimize[4][4] = {{-2.07224649, 13.7948857237, 0.105877704, 9.7924062118},
                                    {32.23703778, -59.4683975703, -1.9077466311, -33.7652110555},
                                    {-68.571074599, 82.0359750338, 9.3496555107, 47.9456096605},
                                    {39.3703274134, -35.364903257, -6.6543490743, -23.9728048165}};
constexpr double kOptimizeOffset = 0.035955884801;
constexpr double kRestore[4][4] = {{0.2227744146, 0.1549679261, 0.1451988946, 0.163127443},
                                   {0.0771972861, 0.1394629426, 0.2120202157, 0.2591432266},
                                   {0.7926986636, 0.7963415838, 0.7258694464, 0.6539092497},
                                   {0.0319417555, -0.1722823173, -0.2758014811, -0.3376131734}};

// mat4 (column-major, columns c[i]) times v: the sum of the columns scaled by v's components.
template <class T> Vec4<T> matTimes(const double (&c)[4][4], const Vec4<T>& v) {
  Vec4<T> r{};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 4; ++k) r[k] += T(c[i][k]) * v[i];
  return r;
}

// moments.frag: (z, z^2, 0, 0) for 2 moments; (z, z^2, z^3, z^4), optionally in the optimized basis.
template <class T> Vec4<T> momentsOf(T z, int moments, bool optimized) {
  const T z2 = z * z;
  if (moments == 2) return {z, z2, T(0), T(0)};
  Vec4<T> m{z, z2, z2 * z, z2 * z2};
  if (!optimized) return m;
  m = matTimes(kOptimize, m);
  m[0] += T(kOptimizeOffset);
  return m;
}

// A texel's fixed-point value in the table (sat.comp's row scan): round((m - offset) * scale) in
// float, then the two's-complement bits as unsigned.
inline uint32_t fixedPoint(float stored, float offset, float scale) {
  const float v = std::nearbyint((stored - offset) * scale);
  return uint32_t(int32_t(v));
}

// The same with WIDE (64-bit sums): round((m - offset) * scale) in float, an integer below 2^63.
inline uint64_t wideFixedPoint(float stored, float offset, float scale) {
  const float v = std::nearbyint((stored - offset) * scale);
  return uint64_t(int64_t(v));
}

// The summed-area table of a square map of `channels`-vector texels (row-major, y up like GL),
// built as sat.comp builds it: unsigned inclusive prefix sums that wrap, 32-bit, or 64-bit with
// `wide` (the low and high words of which the GL table keeps in its left and right halves).
class SummedAreaTable {
public:
  SummedAreaTable(int size, int channels, const std::vector<float>& stored, float offset, float scale, bool wide = false)
      : m_size(size), m_channels(channels), m_wide(wide), m_sums(size_t(size) * size * channels) {
    for (int y = 0; y < size; ++y)
      for (int c = 0; c < channels; ++c) {
        uint64_t run = 0;
        for (int x = 0; x < size; ++x) {
          run += wide ? wideFixedPoint(stored[index(x, y, c)], offset, scale)
                      : uint64_t(fixedPoint(stored[index(x, y, c)], offset, scale));
          if (!wide) run = uint32_t(run);
          m_sums[index(x, y, c)] = run;
        }
      }
    for (int x = 0; x < size; ++x)
      for (int c = 0; c < channels; ++c)
        for (int y = 1; y < size; ++y) {
          m_sums[index(x, y, c)] += m_sums[index(x, y - 1, c)];
          if (!wide) m_sums[index(x, y, c)] = uint32_t(m_sums[index(x, y, c)]);
        }
  }
  int size() const { return m_size; }
  int channels() const { return m_channels; }
  bool wide() const { return m_wide; }
  uint64_t at(int x, int y, int c) const { return x < 0 || y < 0 ? 0u : m_sums[index(x, y, c)]; }

  // boxMoments' four-corner difference over the inclusive texel box [lo, hi], wrapped, as signed.
  Vec4<int64_t> boxSum(int lox, int loy, int hix, int hiy) const {
    Vec4<int64_t> s{};
    for (int c = 0; c < m_channels; ++c) {
      const uint64_t d = at(hix, hiy, c) - at(lox - 1, hiy, c) - at(hix, loy - 1, c) + at(lox - 1, loy - 1, c);
      s[c] = m_wide ? int64_t(d) : int64_t(int32_t(uint32_t(d)));
    }
    return s;
  }

private:
  size_t index(int x, int y, int c) const { return (size_t(y) * m_size + x) * m_channels + c; }
  int m_size, m_channels;
  bool m_wide;
  std::vector<uint64_t> m_sums;
};

// boxMoments' texel box for a lookup at uv (in [0,1]) of half-width `radius` texels: the float
// arithmetic of the shader (the box's corners decide which texels are in).
struct TexelBox {
  int lox, loy, hix, hiy;
  int area() const { return (hix - lox + 1) * (hiy - loy + 1); }
};
inline TexelBox texelBox(float u, float v, float radius, int size) {
  const float r = std::max(radius, 0.5f);
  const float cx = u * float(size), cy = v * float(size);
  auto corner = [size](float x) { return std::clamp(int(std::floor(x)), 0, size - 1); };
  TexelBox b{corner(cx - r), corner(cy - r), corner(cx + r), corner(cy + r)};
  b.hix = std::max(b.hix, b.lox);
  b.hiy = std::max(b.hiy, b.loy);
  return b;
}

// The box mean from its exact sum: vec4(ivec4(sum)) / (area * uSatScale) + uSatOffset; a 64-bit
// table's sum as T(int(high)) * 2^32 + T(low) (boxMoments with uSatWide).
template <class T> Vec4<T> boxMean(const Vec4<int64_t>& sum, int area, double scale, double offset, bool wide) {
  Vec4<T> m{};
  const T denominator = T(area) * T(scale);
  for (int c = 0; c < 4; ++c) {
    const uint64_t bits = uint64_t(sum[c]);
    const T total = wide ? T(int32_t(uint32_t(bits >> 32))) * T(4294967296.0) + T(uint32_t(bits)) : T(sum[c]);
    m[c] = total / denominator + T(offset);
  }
  return m;
}

// moments.glsl's restoreOptimizedMoments: m.x -= offset; m = kRestore * m.
template <class T> Vec4<T> restoreOptimized(Vec4<T> m) {
  m[0] -= T(kOptimizeOffset);
  return matTimes(kRestore, m);
}

// moments.glsl's chebyshevUpperBound.
template <class T> T chebyshevUpperBound(T mu, T m2, T t, T minVariance) {
  const T variance = std::max(m2 - mu * mu, minVariance);
  if (t <= mu) return T(1);
  const T d = t - mu;
  return variance / (variance + d * d);
}

// moments.glsl's momentBlockerDepth: false when the box holds no blocker for t.
template <class T> bool momentBlockerDepth(T mu, T m2, T t, T minVariance, T& zOcc) {
  zOcc = t;
  const T p = chebyshevUpperBound(mu, m2, t, minVariance);
  if (p >= T(0.99)) return false;
  zOcc = std::clamp((mu - p * t) / (T(1) - p), T(0), t);
  return true;
}

template <class T> T reduceBleeding(T p, T amount) { return std::clamp((p - amount) / (T(1) - amount), T(0), T(1)); }

// moments.glsl's hamburger4Msm: the shadow intensity in [0,1] (visibility is 1 minus it). mix(a,
// b, w) as a * (1 - w) + b * w.
template <class T> T hamburger4Msm(const Vec4<T>& moments, T t, T momentBias) {
  Vec4<T> b;
  for (int c = 0; c < 4; ++c) b[c] = moments[c] * (T(1) - momentBias) + T(0.5) * momentBias;
  const T d22 = b[1] - b[0] * b[0];
  const T l32d22 = b[2] - b[0] * b[1];
  const T l32 = l32d22 / d22;
  const T d33 = (b[3] - b[1] * b[1]) - l32 * l32d22;
  T cx = T(1), cy = t, cz = t * t;
  cy -= b[0];
  cz -= b[1] + l32 * cy;
  cy /= d22;
  cz /= d33;
  cy -= l32 * cz;
  cx -= cy * b[0] + cz * b[1];
  const T p = cy / cz;
  const T q = cx / cz;
  const T r = std::sqrt(std::max(p * p * T(0.25) - q, T(0)));
  const T z2 = T(-0.5) * p - r;
  const T z3 = T(-0.5) * p + r;
  if (z3 < t) {
    const T wt = (z2 * z3 - b[0] * (z2 + z3) + b[1]) / ((t - z2) * (t - z3));
    return std::clamp(T(1) - wt, T(0), T(1));
  }
  if (z2 < t) {
    const T w2 = (t * z3 - b[0] * (t + z3) + b[1]) / ((z2 - t) * (z2 - z3));
    return std::clamp(w2, T(0), T(1));
  }
  return T(0);
}

// moments.glsl's momentsAbout: the biased moments about t, E[(z - t)^k], in double, cast to float
// (msm.centred: hamburger4Msm(momentsAbout(m, t, bias), 0, 0) is the same bound, better conditioned).
inline Vec4<float> momentsAbout(const Vec4<double>& m, double t, double momentBias) {
  Vec4<double> b;
  for (int c = 0; c < 4; ++c) b[c] = m[c] * (1.0 - momentBias) + 0.5 * momentBias;
  const double s = t, s2 = s * s;
  return {float(b[0] - s), float(b[1] - 2.0 * s * b[0] + s2), float(b[2] - 3.0 * s * b[1] + 3.0 * s2 * b[0] - s2 * s),
          float(b[3] - 4.0 * s * b[2] + 6.0 * s2 * b[1] - 4.0 * s2 * s * b[0] + s2 * s2)};
}

// A moment map with its table, as the techniques build it: `depths` (normalized, row-major) to
// stored moments to the fixed-point table.
struct MomentMapModel {
  int size = 0;
  int moments = 2;        // 2 (vssm) or 4 (msm)
  bool optimized = false; // msm stores and sums the optimized basis
  Storage storage = Storage::Float32;
  bool wide = false;      // a 64-bit table (`<id>.sat_bits` 64)
  double offset = 0.5;    // uSatOffset (sat_offset on)
  double scale = 131072;  // uSatScale (momentSatScale: 2^17 at the defaults)
  std::vector<float> stored; // `channels()` values per texel, as the moment pass stores them
  int channels() const { return moments == 2 ? 2 : 4; }

  // The moment pass in float (the shader's arithmetic), then the storage's rounding.
  void storeDepths(const std::vector<double>& depths) {
    stored.assign(depths.size() * size_t(channels()), 0.0f);
    for (size_t i = 0; i < depths.size(); ++i) {
      const Vec4<float> m = momentsOf(float(depths[i]), moments, optimized);
      for (int c = 0; c < channels(); ++c) stored[i * channels() + c] = store(m[c], storage);
    }
  }
  SummedAreaTable table() const { return SummedAreaTable(size, channels(), stored, float(offset), float(scale), wide); }

  // The box's raw moment means (z, z^2[, z^3, z^4]) in arithmetic T from the table: boxMoments,
  // then, for msm, the inverse transform.
  template <class T> Vec4<T> boxMoments(const SummedAreaTable& sat, const TexelBox& box) const {
    Vec4<T> m = boxMean<T>(sat.boxSum(box.lox, box.loy, box.hix, box.hiy), box.area(), scale, offset, sat.wide());
    if (moments == 4 && optimized) m = restoreOptimized(m);
    return m;
  }

  // The exact mean of the stored moments over the box in double (no table rounding), restored: the
  // fp64 model's input, what a lossless table would give.
  Vec4<double> storedMean(const TexelBox& box) const {
    Vec4<double> m{};
    for (int y = box.loy; y <= box.hiy; ++y)
      for (int x = box.lox; x <= box.hix; ++x)
        for (int c = 0; c < channels(); ++c) m[c] += double(stored[(size_t(y) * size + x) * channels() + c]);
    for (double& v : m) v /= double(box.area());
    return moments == 4 && optimized ? restoreOptimized(m) : m;
  }
};

// The exact moment means (z^k averaged in double, no storage or table rounding) of a set of depths:
// what the box would give with infinite precision.
inline Vec4<double> exactMoments(const std::vector<double>& depths) {
  Vec4<double> m{};
  for (double z : depths) {
    const double z2 = z * z;
    m[0] += z, m[1] += z2, m[2] += z2 * z, m[3] += z2 * z2;
  }
  for (double& v : m) v /= double(depths.size());
  return m;
}

} // namespace rtlab::moment_model
