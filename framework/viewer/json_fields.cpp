#include "viewer/json_fields.h"

#include "util/error.h"
#include "util/number_format.h"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <limits>

namespace rtlab {
namespace {

std::string quoted(const char* field) {
  return std::string("\"") + field + "\"";
}

// A JSON value for a one-line message: compact, invalid UTF-8 replaced, long values cut.
std::string brief(const nlohmann::json& v) {
  std::string text = v.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  constexpr std::size_t kMax = 60;
  return text.size() <= kMax ? text : text.substr(0, kMax - 3) + "...";
}

[[noreturn]] void wrongType(const char* field, const char* expected, const nlohmann::json& got,
                            const std::string& where) {
  inputError(where + ": " + quoted(field) + " must be " + expected + ", got " + brief(got));
}

const nlohmann::json* find(const nlohmann::json& object, const char* field) {
  auto it = object.find(field);
  return it == object.end() ? nullptr : &*it;
}

const nlohmann::json& require(const nlohmann::json& object, const char* field, const std::string& where) {
  const nlohmann::json* v = find(object, field);
  if (!v) inputError(where + ": missing field " + quoted(field));
  return *v;
}

std::string asString(const nlohmann::json& v, const char* field, const std::string& where) {
  if (!v.is_string()) wrongType(field, "a string", v, where);
  return v.get<std::string>();
}

double asNumber(const nlohmann::json& v, const char* field, const std::string& where) {
  if (!v.is_number()) wrongType(field, "a number", v, where);
  const double x = v.get<double>();
  if (!std::isfinite(x)) usageError(where + ": " + quoted(field) + " must be finite");
  return x;
}

long long asInteger(const nlohmann::json& v, const char* field, const std::string& where) {
  if (!v.is_number_integer()) wrongType(field, "an integer", v, where);
  // get<long long> would wrap an unsigned value above LLONG_MAX to a negative one.
  if (v.is_number_unsigned() && v.get<unsigned long long>() > static_cast<unsigned long long>(LLONG_MAX))
    usageError(where + ": " + quoted(field) + " is too large: " + brief(v));
  return v.get<long long>();
}

bool asBool(const nlohmann::json& v, const char* field, const std::string& where) {
  if (!v.is_boolean()) wrongType(field, "a boolean", v, where);
  return v.get<bool>();
}

glm::vec3 asVec3(const nlohmann::json& v, const char* field, const std::string& where) {
  if (!v.is_array() || v.size() != 3) wrongType(field, "an array of 3 numbers", v, where);
  glm::vec3 out;
  for (int i = 0; i < 3; ++i) {
    if (!v[std::size_t(i)].is_number()) wrongType(field, "an array of 3 numbers", v, where);
    const double x = asNumber(v[std::size_t(i)], field, where);
    if (!(std::abs(x) <= double(std::numeric_limits<float>::max())))
      usageError(where + ": " + quoted(field) + " component " + shortestDecimal(x) + " is out of range");
    out[i] = float(x);
  }
  return out;
}

} // namespace

nlohmann::json parseJsonText(const std::string& text, const std::string& name) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    std::string reason = e.what(); // "[json.exception.parse_error.101] parse error at line 1, ..."
    if (const auto close = reason.find("] "); reason.rfind("[json.exception.", 0) == 0 && close != std::string::npos)
      reason = reason.substr(close + 2);
    inputError(name + " is not valid JSON: " + reason);
  }
}

void requireObject(const nlohmann::json& value, const std::string& where) {
  if (!value.is_object()) inputError(where + " must be a JSON object, got " + brief(value));
}

void rejectUnknownFields(const nlohmann::json& object, const std::vector<const char*>& allowed,
                         const std::string& where) {
  for (const auto& [name, value] : object.items()) {
    bool known = false;
    for (const char* a : allowed)
      known = known || name == a;
    if (known) continue;
    std::string list;
    for (const char* a : allowed)
      list += std::string(list.empty() ? "" : ", ") + a;
    inputError(where + ": unknown field \"" + name + "\"" +
               (list.empty() ? std::string(" (it takes no fields)") : " (known: " + list + ")"));
  }
}

std::string requireString(const nlohmann::json& o, const char* f, const std::string& w) {
  return asString(require(o, f, w), f, w);
}
double requireNumber(const nlohmann::json& o, const char* f, const std::string& w) {
  return asNumber(require(o, f, w), f, w);
}
long long requireInteger(const nlohmann::json& o, const char* f, const std::string& w) {
  return asInteger(require(o, f, w), f, w);
}
bool requireBool(const nlohmann::json& o, const char* f, const std::string& w) {
  return asBool(require(o, f, w), f, w);
}
glm::vec3 requireVec3(const nlohmann::json& o, const char* f, const std::string& w) {
  return asVec3(require(o, f, w), f, w);
}

std::optional<std::string> optionalString(const nlohmann::json& o, const char* f, const std::string& w) {
  const nlohmann::json* v = find(o, f);
  return v ? std::optional(asString(*v, f, w)) : std::nullopt;
}
std::optional<double> optionalNumber(const nlohmann::json& o, const char* f, const std::string& w) {
  const nlohmann::json* v = find(o, f);
  return v ? std::optional(asNumber(*v, f, w)) : std::nullopt;
}
std::optional<long long> optionalInteger(const nlohmann::json& o, const char* f, const std::string& w) {
  const nlohmann::json* v = find(o, f);
  return v ? std::optional(asInteger(*v, f, w)) : std::nullopt;
}
std::optional<bool> optionalBool(const nlohmann::json& o, const char* f, const std::string& w) {
  const nlohmann::json* v = find(o, f);
  return v ? std::optional(asBool(*v, f, w)) : std::nullopt;
}
std::optional<glm::vec3> optionalVec3(const nlohmann::json& o, const char* f, const std::string& w) {
  const nlohmann::json* v = find(o, f);
  return v ? std::optional(asVec3(*v, f, w)) : std::nullopt;
}

std::optional<std::vector<std::string>> optionalStringList(const nlohmann::json& o, const char* f,
                                                           const std::string& w) {
  const nlohmann::json* v = find(o, f);
  if (!v) return std::nullopt;
  if (!v->is_array()) wrongType(f, "an array of strings", *v, w);
  std::vector<std::string> out;
  for (const auto& s : *v) {
    if (!s.is_string()) wrongType(f, "an array of strings", *v, w);
    out.push_back(s.get<std::string>());
  }
  return out;
}

void requireParamValueShape(const nlohmann::json& value, const std::string& what, const std::string& where) {
  const bool numbers = value.is_array() && !value.empty() &&
                       std::all_of(value.begin(), value.end(), [](const nlohmann::json& x) { return x.is_number(); });
  if (value.is_number() || value.is_boolean() || value.is_string() || numbers) return;
  inputError(where + ": " + what + " must be a number, boolean, string or array of numbers, got " + brief(value));
}

void requireChoice(const std::string& value, std::initializer_list<const char*> choices, const char* field,
                   const std::string& where) {
  std::string list;
  for (const char* c : choices) {
    if (value == c) return;
    list += std::string(list.empty() ? "" : ", ") + c;
  }
  usageError(where + ": " + quoted(field) + " must be one of: " + list + " (got '" + value + "')");
}

void requireRange(double value, double lo, double hi, const char* field, const std::string& where) {
  if (value >= lo && value <= hi) return;
  usageError(where + ": " + quoted(field) + " = " + shortestDecimal(value) + " is out of range [" +
             shortestDecimal(lo) + ", " + shortestDecimal(hi) + "]");
}

double jsonNumberFromFloat(float value) {
  // to_chars/from_chars: locale-independent, unlike printf/strtod.
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof(buf), value);
  double out = double(value);
  if (ec == std::errc()) std::from_chars(buf, end, out);
  return out;
}

std::string shortestDecimal(double value) { return formatNumber(value); }

nlohmann::json jsonFromVec3(const glm::vec3& v) {
  return nlohmann::json::array({jsonNumberFromFloat(v.x), jsonNumberFromFloat(v.y), jsonNumberFromFloat(v.z)});
}

} // namespace rtlab
