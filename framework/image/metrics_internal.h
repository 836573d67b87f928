// Shared by metrics.cpp, ssim.cpp and flip.cpp: the prepared pair of images (channels matched,
// valid pixels found, invalid pixels neutralised) and the per-metric kernels.
#pragma once
#include "image/image.h"
#include "image/metrics.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rtlab::detail {

// Rec. 709 / sRGB luminance weights (applied to linear values).
constexpr float kLumR = 0.2126f, kLumG = 0.7152f, kLumB = 0.0722f;

// Two images ready to compare. Same size and channel count (1 or 3; a 1-vs-3 pair becomes 1 vs
// luminance). Each invalid pixel holds, in each image, the values of its nearest valid pixel (0 when
// there is none), so no NaN ever enters a sum and filters that reach across invalid pixels (FLIP)
// see only valid values: every figure depends on the valid pixels alone.
struct PreparedPair {
  int width = 0, height = 0, channels = 0;
  std::vector<float> a, b;            // width * height * channels, row-major, top to bottom
  std::vector<std::uint8_t> valid;    // width * height, 1 = valid
  std::size_t validCount = 0;
  std::size_t nanCount = 0;           // pixels non-finite in either input (mask not considered)
};

// Error(Input) for different sizes, unsupported channel counts or a mask of the wrong size.
PreparedPair preparePair(const Image& a, const Image& b);

// One luminance value per pixel of a prepared image (the value itself when it has one channel).
std::vector<float> luminance(const std::vector<float>& pixels, int channels);

// Mean SSIM over the valid pixels of two one-channel images (ssim.cpp); optional per-pixel map.
double meanSsim(const std::vector<float>& x, const std::vector<float>& y, const std::vector<std::uint8_t>& valid,
                int width, int height, std::vector<float>* map = nullptr);

// Per-pixel LDR-FLIP (flip.cpp) of a prepared pair, with MetricsOptions' input rule.
std::vector<float> flipMap(const PreparedPair& pair, const MetricsOptions& options);

// Per-pixel LDR-FLIP of two linear-RGB images with values in [0,1] (3 floats per pixel), in [0,1].
std::vector<float> ldrFlip(const std::vector<float>& reference, const std::vector<float>& test, int width, int height,
                           double pixelsPerDegree);

} // namespace rtlab::detail
