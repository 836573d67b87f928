// Error metrics between two images over their valid pixels (DESIGN.md "Ground truth and
// metrics", CONTRACT.md compare --json): RMSE, PSNR (peak 1), SSIM (Wang et al. 2004: 11x11
// Gaussian window, sigma 1.5, on luminance), FLIP (Andersson et al. 2020, LDR), max_abs, and the
// count of NaN/Inf pixels, which never poison the other figures.
#pragma once
#include "image/image.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>

namespace rtlab {

struct Metrics {
  double rmse = 0.0;
  std::optional<double> psnr; // empty when the images are identical over the valid pixels
  double ssim = 1.0;
  double flip = 0.0;
  double maxAbs = 0.0;
  std::size_t nanCount = 0;   // pixels with NaN or Inf in either input
  std::size_t validPixels = 0;
};

// Valid pixels: finite in both images, and mask = 1 where an input has a mask (images without a
// mask use all finite pixels). Images of different sizes: Error(Input). Different channel
// counts: a 1-channel image is compared as gray against the other's luminance... see metrics.cpp.
Metrics computeMetrics(const Image& a, const Image& b);

// {"schema": 1, "rmse", "psnr" (null when identical), "ssim", "flip", "max_abs", "nan_count",
//  "valid_pixels"}
nlohmann::ordered_json metricsToJson(const Metrics& m);

// Per-pixel absolute error (mean over channels), 0 on invalid pixels; for heat maps.
Image absoluteErrorImage(const Image& a, const Image& b);

} // namespace rtlab
