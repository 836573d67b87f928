// The one scale of a sweep's error heat maps (docs/sweeps.md "report.html"): a high percentile
// of the per-pixel errors over every point, so that one outlying pixel (a speckle at 1.0) does
// not turn every other heat map black; errors above it are drawn saturated. And the colour bar
// that states the scale on the page.
#pragma once
#include "image/image.h"
#include "util/percentile.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rtlab {

// Adds every valid pixel (mask > 0.5 where the image has one) of a one-channel error image.
void addErrorImage(ErrorPercentile& errors, const Image& error);

// The heat maps' scale: the percentile below (of the nonzero errors), rounded up to two
// significant digits; the largest error when that is 0; 1 when there is no error at all.
constexpr double kHeatPercentile = 0.99;
double heatScale(const ErrorPercentile& errors);

// A horizontal colour bar, `width` x `height` pixels: errors 0 .. scale through the heat maps'
// colormap (errorHeatmap, image/metrics.h), as PNG bytes encoded in base64.
std::string colorBarPngBase64(double scale, int width = 256, int height = 12);

} // namespace rtlab
