#include "app/sweep_heat.h"

#include "image/metrics.h"
#include "util/base64.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace rtlab {
namespace {

double roundUpTwoDigits(double v) {
  if (!(v > 0)) return v;
  const double magnitude = std::pow(10.0, std::floor(std::log10(v)) - 1);
  char text[32]; // through text, so that 0.57 is 0.57 and not 0.5700000000000001
  std::snprintf(text, sizeof text, "%.2g", std::ceil(v / magnitude * (1 - 1e-12)) * magnitude);
  return std::strtod(text, nullptr);
}

} // namespace

void addErrorImage(ErrorPercentile& errors, const Image& error) {
  for (std::size_t i = 0; i < error.pixelCount(); ++i)
    if (!error.hasMask() || error.mask[i] > 0.5f) errors.add(error.pixels[i * std::size_t(error.channels)]);
}

double heatScale(const ErrorPercentile& errors) {
  const double p = errors.percentile(kHeatPercentile);
  if (p > 0) return roundUpTwoDigits(p);
  return errors.max() > 0 ? errors.max() : 1.0;
}

std::string colorBarPngBase64(double scale, int width, int height) {
  Image ramp(width, height, 1);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) ramp.at(x, y, 0) = float(scale * x / std::max(1, width - 1));
  const auto bytes = encodePng(errorHeatmap(ramp, float(scale)));
  return base64Encode(bytes.data(), bytes.size());
}

} // namespace rtlab
