#include "util/percentile.h"

#include <algorithm>
#include <cmath>

namespace rtlab {
namespace {

constexpr int kBinsPerOctave = 32, kMinExponent = -32, kMaxExponent = 32;
constexpr int kBins = (kMaxExponent - kMinExponent) * kBinsPerOctave;

double binUpperEdge(int bin) { return std::exp2(double(bin + 1) / kBinsPerOctave + kMinExponent); }

} // namespace

void ErrorPercentile::add(float value) {
  if (!(value > 0) || !std::isfinite(value)) return;
  if (m_bins.empty()) m_bins.assign(kBins, 0);
  const int bin = std::clamp(int(std::floor((std::log2(double(value)) - kMinExponent) * kBinsPerOctave)), 0, kBins - 1);
  ++m_bins[std::size_t(bin)];
  ++m_count;
  m_max = std::max(m_max, double(value));
}

double ErrorPercentile::percentile(double p) const {
  if (m_count == 0) return 0;
  const auto target = std::uint64_t(std::ceil(std::clamp(p, 0.0, 1.0) * double(m_count)));
  std::uint64_t seen = 0;
  for (int b = 0; b < kBins; ++b) {
    seen += m_bins[std::size_t(b)];
    if (seen >= std::max<std::uint64_t>(target, 1)) return std::min(binUpperEdge(b), m_max);
  }
  return m_max;
}

} // namespace rtlab
