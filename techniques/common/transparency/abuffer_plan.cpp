// The A-buffer's memory plan (abuffer_plan.h).
#include "techniques/common/transparency/abuffer_plan.h"

#include <algorithm>
#include <cmath>

namespace rtlab::abuffer {

std::uint64_t maxNodes(std::uint64_t budgetBytes, std::uint64_t glBlockLimitBytes) {
  const std::uint64_t bytes = std::min(budgetBytes, glBlockLimitBytes);
  return std::clamp<std::uint64_t>(bytes / kNodeBytes, 1, kEndOfList - 1);
}

int bandCount(std::uint64_t expectedNodes, std::uint64_t maxNodes, int height) {
  const double bandsNeeded = std::ceil(1.1 * double(expectedNodes) / double(std::max<std::uint64_t>(maxNodes, 1)));
  return int(std::clamp(bandsNeeded, 1.0, double(std::max(height, 1))));
}

std::vector<Rect> bands(int width, int height, int count) {
  count = std::clamp(count, 1, std::max(height, 1));
  std::vector<Rect> out;
  int y = 0;
  for (int i = 0; i < count; ++i) {
    const int rows = height / count + (i < height % count ? 1 : 0);
    out.push_back(Rect{0, y, width, rows});
    y += rows;
  }
  return out;
}

std::uint64_t grownCapacity(std::uint64_t needed, std::uint64_t maxNodes) {
  return std::min<std::uint64_t>(std::max<std::uint64_t>(needed + needed / 4, 1), maxNodes);
}

std::vector<Rect> split(const Rect& rect, std::uint64_t count, std::uint64_t maxNodes) {
  const bool rows = rect.height >= rect.width; // split the longer side
  const int side = rows ? rect.height : rect.width;
  if (side <= 1) return {rect};
  const double wanted = std::ceil(1.25 * double(count) / double(std::max<std::uint64_t>(maxNodes, 1)));
  const int parts = int(std::clamp(wanted, 2.0, double(side)));
  std::vector<Rect> out;
  int at = 0;
  for (int i = 0; i < parts; ++i) {
    const int len = side / parts + (i < side % parts ? 1 : 0);
    out.push_back(rows ? Rect{rect.x, rect.y + at, rect.width, len} : Rect{rect.x + at, rect.y, len, rect.height});
    at += len;
  }
  return out;
}

} // namespace rtlab::abuffer
