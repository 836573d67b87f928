// The exposure readout of a linear colour image (docs/cli.md "--stats", docs/viewer.md): the
// log-average luminance L̄ = exp(mean(log(delta + L))) with delta = 1e-4 (Reinhard et al. 2002,
// "Photographic Tone Reproduction for Digital Images", eq. 1), the largest luminance, and the "key"
// exposure 0.18 / L̄ that maps L̄ to middle grey. L is Rec. 709 luminance (0.2126 R + 0.7152 G +
// 0.0722 B; a 1-channel image is its own), a negative L counts as 0. Every pixel counts,
// background included (it is part of the frame that the exposure applies to); non-finite pixels are
// left out and counted.
#pragma once
#include "image/image.h"

#include <cstddef>

namespace rtlab {

constexpr double kExposureDelta = 1e-4;  // keeps log() finite on black pixels
constexpr double kMiddleGrey = 0.18;     // the key value L̄ is mapped to

struct ExposureReadout {
  double logAverageLuminance = kExposureDelta; // exp(mean(log(delta + L))), delta not subtracted
  double maxLuminance = 0.0;
  double keyExposure = kMiddleGrey / kExposureDelta; // kMiddleGrey / logAverageLuminance
  std::size_t pixels = 0;    // the finite pixels averaged
  std::size_t nonFinite = 0; // pixels left out (NaN or Inf in a channel)
};

// Accumulates pixels one at a time; the CPU readout and the viewer's GPU tiles both end here.
class ExposureSum {
public:
  // Adds one pixel's luminance (left out and counted when not finite).
  void add(double luminance);
  // Adds a partial sum of `count` finite pixels: their sum of log(delta + L) and their largest L.
  void addPartial(double sumLog, double maxLuminance, std::size_t count);
  void addNonFinite(std::size_t count) { m_nonFinite += count; }
  ExposureReadout readout() const;

private:
  double m_sumLog = 0.0, m_max = 0.0;
  std::size_t m_count = 0, m_nonFinite = 0;
};

// The readout of a 1- or 3-channel image, over every pixel. An image without pixels gives
// logAverageLuminance = delta (as a black frame would).
ExposureReadout measureExposure(const Image& color);

} // namespace rtlab
