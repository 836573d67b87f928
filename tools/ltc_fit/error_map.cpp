#include "error_map.h"

#include "image/metrics.h"

namespace rtlab::ltcfit {

Image ltcErrorMap(const LtcTable& table, float maxError, int scale) {
  const int n = table.size, side = n * scale, gap = scale, bar = 4 * scale;
  Image error(side, side + gap + bar, 1);
  error.mask.assign(error.pixelCount(), 1.0f);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) error.at(x, y, 0) = table.errorAt(x / scale, y / scale);
  for (int y = side; y < side + gap; ++y)
    for (int x = 0; x < side; ++x) error.mask[std::size_t(y) * std::size_t(side) + std::size_t(x)] = 0.0f; // gray
  for (int y = side + gap; y < error.height; ++y)
    for (int x = 0; x < side; ++x) error.at(x, y, 0) = maxError * (float(x) + 0.5f) / float(side);
  return errorHeatmap(error, maxError);
}

} // namespace rtlab::ltcfit
