#include "util/number_format.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace rtlab {
namespace {

template <typename T> std::string shortest(T value) {
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
  if (ec == std::errc()) return std::string(buf, end);
  std::snprintf(buf, sizeof buf, "%.17g", double(value)); // not reached: 64 chars always suffice
  return buf;
}

// Below 2^53 every integral double is exact, and its digits are what the user would type.
constexpr double kExactIntegers = 9007199254740992.0;

} // namespace

std::string formatNumberExact(double value) {
  if (!std::isfinite(value)) return std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf");
  if (value == std::floor(value) && std::abs(value) < kExactIntegers) {
    if (value == 0.0) return "0"; // also -0
    return std::to_string(static_cast<long long>(value));
  }
  return shortest(value);
}

std::string formatNumber(double value) {
  const float f = static_cast<float>(value);
  if (std::isfinite(value) && value != std::floor(value) && static_cast<double>(f) == value) return shortest(f);
  return formatNumberExact(value);
}

std::string formatNumber(float value) { return formatNumber(static_cast<double>(value)); }

} // namespace rtlab
