// Percentiles of a large stream of errors in fixed memory, for the sweep's heat-map scale
// (docs/sweeps.md "report.html").
#pragma once
#include <cstdint>
#include <vector>

namespace rtlab {

// Percentiles of a stream of non-negative values without keeping them: a histogram with 32
// logarithmic bins per octave (about 2% wide) from 2^-32 to 2^32. Zero, negative and non-finite
// values are not counted.
class ErrorPercentile {
public:
  void add(float value);
  // The smallest bin edge at or above the p-th fraction (0 < p <= 1) of the counted values, at
  // most the largest value counted; 0 when nothing was counted.
  double percentile(double p) const;
  double max() const { return m_max; }
  std::uint64_t count() const { return m_count; }

private:
  std::vector<std::uint64_t> m_bins;
  std::uint64_t m_count = 0;
  double m_max = 0;
};

} // namespace rtlab
