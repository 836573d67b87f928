#include "params/sweep_spec.h"

#include "util/error.h"
#include "util/number_format.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>

namespace rtlab {
namespace {

double roundSignificant(double x, int digits) {
  if (x == 0 || !std::isfinite(x)) return x;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return std::strtod(buf, nullptr);
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto pos = text.find(sep, start);
    parts.push_back(text.substr(start, pos == std::string::npos ? std::string::npos : pos - start));
    if (pos == std::string::npos) break;
    start = pos + 1;
  }
  return parts;
}

void addUnique(std::vector<std::string>& values, const std::string& v) {
  if (std::find(values.begin(), values.end(), v) == values.end()) values.push_back(v);
}

std::vector<std::string> expandRange(const ParamSpec& spec, const std::string& text) {
  const auto parts = split(text, ':');
  if (parts.size() != 3)
    usageError("invalid --vary range '" + text + "' for '" + spec.key + "': expected LO:HI:N");
  const double lo = parseParamValue(spec, parts[0]).v[0];
  const double hi = parseParamValue(spec, parts[1]).v[0];
  long long n = 0;
  const std::string& nText = parts[2];
  auto [ptr, ec] = std::from_chars(nText.data(), nText.data() + nText.size(), n);
  if (nText.empty() || ec != std::errc() || ptr != nText.data() + nText.size() || n < 2 || n > 100000)
    usageError("invalid point count '" + nText + "' in --vary " + spec.key + "=" + text +
               ": expected an integer N in [2, 100000]");
  const bool logScale = spec.scale == ParamScale::Log;
  if (logScale && !(lo > 0 && hi > 0))
    usageError("'" + spec.key + "' has a log scale: --vary " + spec.key + "=LO:HI:N needs LO > 0 and HI > 0 (got '" +
               text + "')");
  std::vector<std::string> values;
  const double low = std::min(lo, hi), high = std::max(lo, hi);
  for (long long i = 0; i < n; ++i) {
    double v;
    if (i == 0) v = lo;
    else if (i == n - 1) v = hi;
    else {
      const double t = double(i) / double(n - 1);
      v = logScale ? std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * t) : lo + (hi - lo) * t;
      v = spec.type == ParamType::Int ? double(std::llround(v)) : roundSignificant(v, 6);
      v = std::clamp(v, low, high);
    }
    ParamValue value = ParamValue::scalar(v);
    checkParamRange(spec, value);
    addUnique(values, canonicalParamText(spec, value));
  }
  return values;
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

} // namespace

std::pair<std::string, std::string> splitVaryArgument(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    usageError("invalid --vary '" + text + "': expected KEY=V1,V2,... or KEY=LO:HI:N");
  return {text.substr(0, eq), text.substr(eq + 1)};
}

std::string canonicalParamText(const ParamSpec& spec, const ParamValue& value) {
  switch (spec.type) {
  case ParamType::Float: return formatNumberExact(value.v[0]);
  case ParamType::Int: return std::to_string(std::llround(value.v[0]));
  case ParamType::Bool: return value.v[0] != 0 ? "true" : "false";
  case ParamType::Enum: {
    const long long i = std::llround(value.v[0]);
    if (i < 0 || i >= (long long)spec.choices.size()) return std::to_string(i);
    return spec.choices[std::size_t(i)];
  }
  case ParamType::Vec3:
  case ParamType::Color:
    return formatNumberExact(value.v[0]) + "," + formatNumberExact(value.v[1]) + "," + formatNumberExact(value.v[2]);
  }
  return "";
}

std::vector<std::string> expandSweepValues(const ParamSpec& spec, const std::string& text) {
  if (text.empty()) usageError("--vary " + spec.key + "= has no values");
  const bool vector = spec.components() == 3;
  if (!vector && text.find(':') != std::string::npos) {
    if (!spec.isNumeric())
      usageError("--vary " + spec.key + "=" + text + ": LO:HI:N ranges are for float and int keys; list the values (" +
                 describeRange(spec) + ")");
    return expandRange(spec, text);
  }
  std::vector<std::string> values;
  for (const auto& item : split(text, vector ? ';' : ',')) {
    if (item.empty())
      usageError("invalid --vary " + spec.key + "=" + text + ": empty value in the list" +
                 (vector ? " (vec3 and color values are separated by ';')" : ""));
    addUnique(values, canonicalParamText(spec, parseParamValue(spec, item)));
  }
  return values;
}

bool isLightKey(const std::string& key) {
  if (!startsWith(key, "light")) return false;
  std::size_t i = 5;
  while (i < key.size() && std::isdigit(static_cast<unsigned char>(key[i]))) ++i;
  return i > 5 && i < key.size() && key[i] == '.';
}

bool sweepKeyApplies(const std::string& key, const SweepTechnique& technique) {
  const std::string prefix = key.substr(0, key.find('.'));
  if (prefix == technique.id || prefix == technique.stage) return true;
  return prefix == "tonemap" || prefix == "camera" || isLightKey(key);
}

std::vector<SweepGridPoint> buildSweepGrid(const std::vector<SweepTechnique>& techniques,
                                           const std::vector<SweepAxis>& axes, std::size_t maxPoints) {
  std::set<std::string> seen;
  for (const auto& axis : axes) {
    if (!seen.insert(axis.key).second) usageError("--vary '" + axis.key + "' is given twice");
    if (axis.values.empty()) usageError("--vary '" + axis.key + "' has no values");
    const bool applies = std::any_of(techniques.begin(), techniques.end(),
                                     [&](const SweepTechnique& t) { return sweepKeyApplies(axis.key, t); });
    if (!applies) {
      std::string ids;
      for (const auto& t : techniques) ids += (ids.empty() ? "" : ", ") + t.id;
      usageError("--vary '" + axis.key + "' does not affect the techniques swept (" + ids + "; stage '" +
                 (techniques.empty() ? std::string("?") : techniques.front().stage) +
                 "'): vary their own keys, the stage's, tonemap.*, light<N>.* or camera.*");
    }
  }
  std::vector<SweepGridPoint> points;
  for (const auto& t : techniques) {
    std::vector<const SweepAxis*> mine;
    std::size_t count = 1;
    for (const auto& axis : axes) {
      if (!sweepKeyApplies(axis.key, t)) continue;
      mine.push_back(&axis);
      count *= axis.values.size();
      if (count > maxPoints) break;
    }
    if (count > maxPoints || points.size() + count > maxPoints)
      usageError("the sweep has more than " + std::to_string(maxPoints) + " points; vary fewer values");
    // Odometer over the axes, the last one fastest.
    std::vector<std::size_t> digit(mine.size(), 0);
    for (std::size_t n = 0; n < count; ++n) {
      SweepGridPoint p{t.id, {}};
      for (std::size_t a = 0; a < mine.size(); ++a) p.values.emplace_back(mine[a]->key, mine[a]->values[digit[a]]);
      points.push_back(std::move(p));
      for (std::size_t a = mine.size(); a-- > 0;) {
        if (++digit[a] < mine[a]->values.size()) break;
        digit[a] = 0;
      }
    }
  }
  return points;
}

} // namespace rtlab
