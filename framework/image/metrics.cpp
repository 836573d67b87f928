// Error metrics over valid pixels (metrics.h, docs/metrics.md): the pair preparation (sizes,
// channels, mask, NaN/Inf), RMSE, PSNR with peak 1, max_abs, and the JSON of docs/contract.md.
// SSIM lives in ssim.cpp, FLIP in flip.cpp, the heat-map colours in heatmap.cpp.
#include "image/metrics.h"
#include "image/metrics_internal.h"

#include "util/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace rtlab {
namespace detail {
namespace {

std::string sizeText(const Image& image) { return std::to_string(image.width) + "x" + std::to_string(image.height); }

void checkImage(const Image& image, const char* which) {
  if (image.channels != 1 && image.channels != 3)
    inputError(std::string("image ") + which + " has " + std::to_string(image.channels) +
               " channels (metrics need 1 or 3)");
  if (image.width <= 0 || image.height <= 0 || image.pixels.size() != image.pixelCount() * image.channels)
    inputError(std::string("image ") + which + " is empty or its pixel buffer does not match " + sizeText(image));
  if (image.hasMask() && image.mask.size() != image.pixelCount())
    inputError(std::string("image ") + which + " has a mask of " + std::to_string(image.mask.size()) +
               " values for " + std::to_string(image.pixelCount()) + " pixels");
}

// The image with `channels` channels: unchanged, or its luminance when going from 3 to 1.
std::vector<float> withChannels(const Image& image, int channels) {
  if (image.channels == channels) return image.pixels;
  return luminance(image.pixels, image.channels);
}

bool pixelFinite(const float* p, int channels) {
  for (int c = 0; c < channels; ++c)
    if (!std::isfinite(p[c])) return false;
  return true;
}

bool masked(const Image& image, std::size_t i) { return image.hasMask() && !(image.mask[i] > 0.5f); }

// Each invalid pixel takes, in each image, the values of its nearest valid pixel (multi-source
// breadth-first search over 4-neighbours, so Manhattan distance, ties in scan order); 0 when there
// is no valid pixel. Filters that reach across invalid pixels then see only valid values.
void fillInvalid(PreparedPair& pair) {
  const int w = pair.width, h = pair.height, c = pair.channels;
  const std::size_t n = pair.valid.size();
  if (pair.validCount == n) return;
  if (pair.validCount == 0) {
    std::fill(pair.a.begin(), pair.a.end(), 0.0f);
    std::fill(pair.b.begin(), pair.b.end(), 0.0f);
    return;
  }
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> source(n, kNone), queue;
  queue.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    if (pair.valid[i]) {
      source[i] = i;
      queue.push_back(i);
    }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::size_t i = queue[head];
    const int x = int(i % w), y = int(i / w);
    const std::size_t next[4] = {x > 0 ? i - 1 : kNone, x + 1 < w ? i + 1 : kNone, y > 0 ? i - w : kNone,
                                 y + 1 < h ? i + w : kNone};
    for (std::size_t j : next) {
      if (j == kNone || source[j] != kNone) continue;
      source[j] = source[i];
      for (int k = 0; k < c; ++k) {
        pair.a[j * c + k] = pair.a[source[i] * c + k];
        pair.b[j * c + k] = pair.b[source[i] * c + k];
      }
      queue.push_back(j);
    }
  }
}

} // namespace

std::vector<float> luminance(const std::vector<float>& pixels, int channels) {
  if (channels == 1) return pixels;
  const std::size_t n = pixels.size() / 3;
  std::vector<float> y(n);
  for (std::size_t i = 0; i < n; ++i)
    y[i] = kLumR * pixels[3 * i] + kLumG * pixels[3 * i + 1] + kLumB * pixels[3 * i + 2];
  return y;
}

PreparedPair preparePair(const Image& a, const Image& b) {
  checkImage(a, "A");
  checkImage(b, "B");
  if (a.width != b.width || a.height != b.height)
    inputError("images differ in size: " + sizeText(a) + " and " + sizeText(b));

  PreparedPair pair;
  pair.width = a.width;
  pair.height = a.height;
  pair.channels = std::min(a.channels, b.channels);
  const int c = pair.channels;
  pair.a = withChannels(a, c);
  pair.b = withChannels(b, c);
  const std::size_t n = a.pixelCount();
  pair.valid.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    // Counted on the inputs as given (a NaN or Inf in any channel), background included.
    const bool finiteA = pixelFinite(&a.pixels[i * a.channels], a.channels);
    const bool finiteB = pixelFinite(&b.pixels[i * b.channels], b.channels);
    if (!finiteA || !finiteB) ++pair.nanCount;
    if (finiteA && finiteB && !masked(a, i) && !masked(b, i)) {
      pair.valid[i] = 1;
      ++pair.validCount;
    }
  }
  fillInvalid(pair);
  return pair;
}

} // namespace detail

double pixelsPerDegree(const MetricsOptions& o) {
  // Andersson et al. 2020, Section 2 (viewing conditions): p = d * (r / w) * pi / 180.
  return o.viewingDistanceMeters * (o.displayWidthPixels / o.displayWidthMeters) * std::numbers::pi / 180.0;
}

Metrics computeMetrics(const Image& a, const Image& b, const MetricsOptions& options) {
  const detail::PreparedPair pair = detail::preparePair(a, b);
  Metrics m;
  m.nanCount = pair.nanCount;
  m.validPixels = pair.validCount;
  if (pair.validCount == 0) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    m.rmse = m.ssim = m.flip = m.maxAbs = nan;
    m.psnr.reset();
    return m;
  }

  const int c = pair.channels;
  double sumSq = 0.0, maxAbs = 0.0;
  for (std::size_t i = 0; i < pair.valid.size(); ++i) {
    if (!pair.valid[i]) continue;
    for (int k = 0; k < c; ++k) {
      const double d = double(pair.a[i * c + k]) - double(pair.b[i * c + k]);
      sumSq += d * d;
      maxAbs = std::max(maxAbs, std::abs(d));
    }
  }
  const double mse = sumSq / (double(pair.validCount) * c);
  m.rmse = std::sqrt(mse);
  m.maxAbs = maxAbs;
  if (mse > 0.0) m.psnr = 10.0 * std::log10(1.0 / mse); // peak 1

  const std::vector<float> ya = detail::luminance(pair.a, c);
  const std::vector<float> yb = detail::luminance(pair.b, c);
  m.ssim = detail::meanSsim(ya, yb, pair.valid, pair.width, pair.height);

  const std::vector<float> flip = detail::flipMap(pair, options);
  double flipSum = 0.0;
  for (std::size_t i = 0; i < flip.size(); ++i)
    if (pair.valid[i]) flipSum += flip[i];
  m.flip = flipSum / double(pair.validCount);
  return m;
}

nlohmann::ordered_json metricsToJson(const Metrics& m) {
  auto number = [](double v) -> nlohmann::ordered_json {
    if (!std::isfinite(v)) return nullptr;
    return v;
  };
  nlohmann::ordered_json j;
  j["schema"] = 1;
  j["rmse"] = number(m.rmse);
  j["psnr"] = m.psnr ? number(*m.psnr) : nlohmann::ordered_json(nullptr);
  j["ssim"] = number(m.ssim);
  j["flip"] = number(m.flip);
  j["max_abs"] = number(m.maxAbs);
  j["nan_count"] = m.nanCount;
  j["valid_pixels"] = m.validPixels;
  return j;
}

Image absoluteErrorImage(const Image& a, const Image& b) {
  const detail::PreparedPair pair = detail::preparePair(a, b);
  const int c = pair.channels;
  Image out(pair.width, pair.height, 1);
  out.mask.assign(pair.valid.size(), 0.0f);
  for (std::size_t i = 0; i < pair.valid.size(); ++i) {
    if (!pair.valid[i]) continue;
    double sum = 0.0;
    for (int k = 0; k < c; ++k) sum += std::abs(double(pair.a[i * c + k]) - double(pair.b[i * c + k]));
    out.pixels[i] = float(sum / c);
    out.mask[i] = 1.0f;
  }
  return out;
}

} // namespace rtlab
