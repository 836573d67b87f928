#include "image/exposure.h"

#include <algorithm>
#include <cmath>

namespace rtlab {

void ExposureSum::add(double luminance) {
  if (!std::isfinite(luminance)) {
    ++m_nonFinite;
    return;
  }
  const double l = std::max(luminance, 0.0);
  m_sumLog += std::log(kExposureDelta + l);
  m_max = std::max(m_max, l);
  ++m_count;
}

void ExposureSum::addPartial(double sumLog, double maxLuminance, std::size_t count) {
  if (count == 0) return;
  m_sumLog += sumLog;
  m_max = std::max(m_max, maxLuminance);
  m_count += count;
}

ExposureReadout ExposureSum::readout() const {
  ExposureReadout r;
  r.pixels = m_count;
  r.nonFinite = m_nonFinite;
  r.maxLuminance = m_max;
  r.logAverageLuminance = m_count > 0 ? std::exp(m_sumLog / double(m_count)) : kExposureDelta;
  r.keyExposure = kMiddleGrey / r.logAverageLuminance;
  return r;
}

ExposureReadout measureExposure(const Image& color) {
  ExposureSum sum;
  const std::size_t n = color.pixelCount();
  for (std::size_t i = 0; i < n; ++i) {
    const float* p = color.pixels.data() + i * std::size_t(color.channels);
    if (color.channels == 1) {
      sum.add(p[0]);
      continue;
    }
    const bool finite = std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
    if (finite)
      sum.add(0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]);
    else
      sum.addNonFinite(1);
  }
  return sum.readout();
}

} // namespace rtlab
