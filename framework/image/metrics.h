// Error metrics between two images over their valid pixels (docs/contract.md
// "compare --json"): RMSE, PSNR (peak 1), SSIM (Wang et al. 2004: 11x11
// Gaussian window, sigma 1.5, on luminance), FLIP (Andersson et al. 2020, LDR), max_abs, and the
// count of NaN/Inf pixels, which never poison the other figures. docs/metrics.md explains each.
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

// How FLIP reads the values (docs/metrics.md "FLIP"). FLIP compares what a display shows, in [0,1].
struct MetricsOptions {
  // false: 3-channel values are linear RGB (EXR/PFM color, indirect, albedo), clamped to [0,1]
  //        (exposure 1, no tone curve); 1-channel values are display gray levels, as the PNG
  //        previews of data AOVs show them.
  // true:  every value is a display (sRGB-encoded) value in [0,1], as read from PNG files.
  bool displayEncoded = false;
  // Viewing conditions: FLIP's default, 0.7 m from a 0.7 m wide, 3840-pixel display (67 px/degree).
  double viewingDistanceMeters = 0.7;
  double displayWidthMeters = 0.7;
  double displayWidthPixels = 3840.0;
};

// Pixels per degree of visual angle for the viewing conditions (FLIP's default: 67.02).
double pixelsPerDegree(const MetricsOptions& options);

// Valid pixels: finite in both images, and mask = 1 (> 0.5) where an input has a mask (images
// without a mask use all finite pixels). Images of different sizes, or with a channel count other
// than 1 or 3: Error(Input).
// Channels: RMSE, PSNR and max_abs run over every channel of the valid pixels (MSE = sum of squared
// differences / (valid pixels * channels)). When the channel counts differ (1 vs 3), the 3-channel
// image is reduced to its Rec. 709 luminance (0.2126 R + 0.7152 G + 0.0722 B) and every metric
// compares one channel. SSIM runs on luminance (Rec. 709 weights on the values as stored; a
// 1-channel image is its own luminance), with the window weighted by the valid mask. FLIP: see
// MetricsOptions. With no valid pixel, rmse, ssim, flip and max_abs are NaN (null in JSON) and psnr
// is empty: there is nothing to measure.
Metrics computeMetrics(const Image& a, const Image& b, const MetricsOptions& options = {});

// {"schema": 1, "rmse", "psnr" (null when identical), "ssim", "flip", "max_abs", "nan_count",
//  "valid_pixels"}; a non-finite figure is written as null.
nlohmann::ordered_json metricsToJson(const Metrics& m);

// Per-pixel absolute error (mean over channels; luminance when the channel counts differ), 0 on
// invalid pixels; for heat maps. The result has one channel and a mask: 1 valid, 0 invalid.
Image absoluteErrorImage(const Image& a, const Image& b);

// Per-pixel LDR-FLIP error in [0,1] (the map whose mean over valid pixels is Metrics::flip), 0 on
// invalid pixels; one channel, mask 1 valid / 0 invalid. Implemented in flip.cpp.
Image flipErrorImage(const Image& a, const Image& b, const MetricsOptions& options = {});

// Heat map of a one-channel error image for reports: error / maxError, clamped to [0,1], through
// the magma colormap (perceptually uniform; the colormap FLIP's paper uses for its error maps).
// Returns 3 channels of display (sRGB-encoded) values: write them to PNG with the default
// PngEncoding::Linear01, which stores them unchanged. Pixels whose mask is 0 are drawn mid gray
// (0.5); maxError <= 0 maps every nonzero error to the top of the scale.
Image errorHeatmap(const Image& error, float maxError);

} // namespace rtlab
