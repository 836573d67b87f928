#include "image/preview.h"

#include "image/metrics.h"
#include "util/error.h"
#include "util/number_format.h"

#include <charconv>
#include <cmath>

namespace rtlab {
namespace {

bool parseFloat(std::string_view s, float& out) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return false;
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && ptr == s.data() + s.size() && std::isfinite(out);
}

} // namespace

std::optional<PreviewRange> parsePreviewRange(const std::string& option, const std::string& text) {
  if (text == "auto") return std::nullopt;
  const auto colon = text.find(':');
  PreviewRange r;
  if (colon == std::string::npos || !parseFloat(std::string_view(text).substr(0, colon), r.lo) ||
      !parseFloat(std::string_view(text).substr(colon + 1), r.hi))
    usageError("invalid " + option + " '" + text + "': expected LO:HI (two decimal numbers, LO < HI) or auto");
  if (!(r.lo < r.hi))
    usageError("invalid " + option + " '" + text + "': LO (" + formatNumber(r.lo) + ") must be less than HI (" +
               formatNumber(r.hi) + ")");
  return r;
}

PreviewRange autoPreviewRange(const Image& data) {
  const ValueRange v = validRange(data);
  if (v.empty()) return {};
  if (v.min < v.max) return {v.min, v.max};
  return {v.min - 0.5f, v.min + 0.5f};
}

Image previewImage(const Image& data, PreviewRange range, bool falseColor) {
  if (falseColor && data.channels != 1)
    throw Error(ExitCode::Internal, "a false-colour preview needs one channel, got " + std::to_string(data.channels));
  Image mapped(data.width, data.height, data.channels);
  mapped.mask = data.mask;
  const double scale = 1.0 / (double(range.hi) - double(range.lo));
  const std::size_t n = data.pixelCount();
  for (std::size_t p = 0; p < n; ++p) {
    const bool valid = !data.hasMask() || data.mask[p] > 0.5f;
    for (int c = 0; c < data.channels; ++c) {
      const std::size_t i = p * data.channels + c;
      mapped.pixels[i] = valid ? float((double(data.pixels[i]) - range.lo) * scale) : 0.0f;
    }
  }
  if (!falseColor) return mapped;
  Image colored = errorHeatmap(mapped, 1.0f); // t in [0, 1] on the magma map, background gray
  colored.mask = data.mask;
  return colored;
}

} // namespace rtlab
