#include "params/param_spec.h"

#include "util/error.h"
#include "util/number_format.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace rtlab {
namespace {

std::string joinChoices(const std::vector<std::string>& choices) {
  std::string s;
  for (std::size_t i = 0; i < choices.size(); ++i) s += (i ? ", " : "") + choices[i];
  return s;
}

[[noreturn]] void badValue(const ParamSpec& spec, const std::string& text, const std::string& why) {
  usageError("invalid value '" + text + "' for '" + spec.key + "': " + why + " (" + paramTypeName(spec.type) +
             ", " + describeRange(spec) + ")");
}

bool parseDouble(std::string_view s, double& out) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  // One optional sign: from_chars takes '-' but not '+', so strip a '+' and refuse "+-1" / "++1".
  if (!s.empty() && s.front() == '+') {
    s.remove_prefix(1);
    if (!s.empty() && (s.front() == '-' || s.front() == '+')) return false;
  }
  if (s.empty()) return false;
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && ptr == s.data() + s.size() && std::isfinite(out);
}

} // namespace

const char* paramTypeName(ParamType type) {
  switch (type) {
  case ParamType::Float: return "float";
  case ParamType::Int: return "int";
  case ParamType::Bool: return "bool";
  case ParamType::Enum: return "enum";
  case ParamType::Vec3: return "vec3";
  case ParamType::Color: return "color";
  }
  return "?";
}

ParamSpec ParamSpec::real(std::string key, std::string label, double def, double min, double max) {
  ParamSpec s;
  s.key = std::move(key);
  s.label = std::move(label);
  s.type = ParamType::Float;
  s.def = ParamValue::scalar(def);
  s.min = min;
  s.max = max;
  return s;
}

ParamSpec ParamSpec::integer(std::string key, std::string label, int def, int min, int max) {
  ParamSpec s = real(std::move(key), std::move(label), def, min, max);
  s.type = ParamType::Int;
  return s;
}

ParamSpec ParamSpec::boolean(std::string key, std::string label, bool def) {
  ParamSpec s = real(std::move(key), std::move(label), def ? 1 : 0, 0, 1);
  s.type = ParamType::Bool;
  return s;
}

ParamSpec ParamSpec::choice(std::string key, std::string label, std::vector<std::string> choices, int def) {
  ParamSpec s = real(std::move(key), std::move(label), def, 0, double(choices.size()) - 1);
  s.type = ParamType::Enum;
  s.choices = std::move(choices);
  return s;
}

ParamSpec ParamSpec::vector3(std::string key, std::string label, glm::vec3 def, double min, double max) {
  ParamSpec s = real(std::move(key), std::move(label), 0, min, max);
  s.type = ParamType::Vec3;
  s.def = ParamValue::vec3(def);
  return s;
}

ParamSpec ParamSpec::color(std::string key, std::string label, glm::vec3 def, double min, double max) {
  ParamSpec s = vector3(std::move(key), std::move(label), def, min, max);
  s.type = ParamType::Color;
  return s;
}

std::string describeRange(const ParamSpec& spec) {
  switch (spec.type) {
  case ParamType::Bool: return "true|false|1|0|on|off";
  case ParamType::Enum: return "one of: " + joinChoices(spec.choices);
  case ParamType::Vec3:
  case ParamType::Color:
    return "x,y,z each in [" + formatNumber(spec.min) + ", " + formatNumber(spec.max) + "]";
  default: return "range [" + formatNumber(spec.min) + ", " + formatNumber(spec.max) + "]";
  }
}

void checkParamRange(const ParamSpec& spec, const ParamValue& value) {
  const int n = spec.components();
  for (int i = 0; i < n; ++i) {
    const double x = value.v[i];
    const bool integral = spec.type != ParamType::Float && spec.type != ParamType::Vec3 && spec.type != ParamType::Color;
    // Printed exactly: a value just outside the range must not read as the bound itself.
    const std::string shown = (spec.type == ParamType::Vec3 || spec.type == ParamType::Color)
                                  ? formatNumber(value.v[0]) + "," + formatNumber(value.v[1]) + "," + formatNumber(value.v[2])
                                  : formatNumber(x);
    if (!std::isfinite(x) || x < spec.min || x > spec.max)
      usageError("value " + shown + " for '" + spec.key + "' is out of " + describeRange(spec));
    if (integral && x != std::floor(x))
      usageError("value " + shown + " for '" + spec.key + "' is not an integer (" + paramTypeName(spec.type) + ", " +
                 describeRange(spec) + ")");
  }
}

ParamValue parseParamValue(const ParamSpec& spec, const std::string& text) {
  ParamValue v;
  switch (spec.type) {
  case ParamType::Float:
    if (!parseDouble(text, v.v[0])) badValue(spec, text, "not a finite decimal number");
    break;
  case ParamType::Int: {
    std::string_view s = text;
    if (!s.empty() && s.front() == '+') {
      s.remove_prefix(1);
      if (!s.empty() && (s.front() == '-' || s.front() == '+')) badValue(spec, text, "not an integer"); // "+-1"
    }
    long long i = 0;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), i);
    if (s.empty() || ec != std::errc() || ptr != s.data() + s.size()) badValue(spec, text, "not an integer");
    v.v[0] = double(i);
    break;
  }
  case ParamType::Bool:
    if (text == "true" || text == "1" || text == "on") v.v[0] = 1;
    else if (text == "false" || text == "0" || text == "off") v.v[0] = 0;
    else badValue(spec, text, "not a bool");
    break;
  case ParamType::Enum: {
    auto it = std::find(spec.choices.begin(), spec.choices.end(), text);
    if (it == spec.choices.end()) badValue(spec, text, "unknown choice");
    v.v[0] = double(it - spec.choices.begin());
    break;
  }
  case ParamType::Vec3:
  case ParamType::Color: {
    std::string_view s = text;
    for (int i = 0; i < 3; ++i) {
      auto comma = s.find(',');
      std::string_view part = (i < 2) ? s.substr(0, comma) : s;
      if ((i < 2 && comma == std::string_view::npos) || (i == 2 && s.find(',') != std::string_view::npos) ||
          !parseDouble(part, v.v[i]))
        badValue(spec, text, "expected x,y,z");
      if (i < 2) s.remove_prefix(comma + 1);
    }
    break;
  }
  }
  checkParamRange(spec, v);
  return v;
}

ParamValue paramValueFromJson(const ParamSpec& spec, const nlohmann::json& j) {
  ParamValue v;
  const std::string text = j.dump();
  switch (spec.type) {
  case ParamType::Float:
  case ParamType::Int:
    if (!j.is_number()) badValue(spec, text, "expected a number");
    v.v[0] = j.get<double>();
    break;
  case ParamType::Bool:
    if (j.is_boolean()) v.v[0] = j.get<bool>() ? 1 : 0;
    else if (j.is_number_integer() && (j.get<long long>() == 0 || j.get<long long>() == 1)) v.v[0] = j.get<double>();
    else badValue(spec, text, "expected true or false");
    break;
  case ParamType::Enum:
    if (!j.is_string()) badValue(spec, text, "expected a choice name");
    return parseParamValue(spec, j.get<std::string>());
  case ParamType::Vec3:
  case ParamType::Color:
    if (!j.is_array() || j.size() != 3) badValue(spec, text, "expected an array of 3 numbers");
    for (int i = 0; i < 3; ++i) {
      if (!j[i].is_number()) badValue(spec, text, "expected an array of 3 numbers");
      v.v[i] = j[i].get<double>();
    }
    break;
  }
  checkParamRange(spec, v);
  return v;
}

std::string formatParamValue(const ParamSpec& spec, const ParamValue& value) {
  switch (spec.type) {
  case ParamType::Bool: return value.v[0] != 0 ? "true" : "false";
  case ParamType::Enum: {
    const double x = value.v[0];
    // Guarded: converting a negative or non-finite double to size_t is undefined.
    if (!(x >= 0.0 && x < double(spec.choices.size())) || x != std::floor(x)) return formatNumber(x);
    return spec.choices[std::size_t(x)];
  }
  case ParamType::Vec3:
  case ParamType::Color:
    return formatNumber(value.v[0]) + "," + formatNumber(value.v[1]) + "," + formatNumber(value.v[2]);
  default: return formatNumber(value.v[0]);
  }
}

nlohmann::json paramValueToJson(const ParamSpec& spec, const ParamValue& value) {
  switch (spec.type) {
  case ParamType::Float: return value.v[0];
  case ParamType::Int: return static_cast<long long>(value.v[0]);
  case ParamType::Bool: return value.v[0] != 0;
  case ParamType::Enum: return formatParamValue(spec, value);
  case ParamType::Vec3:
  case ParamType::Color: return nlohmann::json::array({value.v[0], value.v[1], value.v[2]});
  }
  return nullptr;
}

nlohmann::ordered_json paramSpecToJson(const ParamSpec& spec) {
  nlohmann::ordered_json p;
  p["key"] = spec.key;
  p["label"] = spec.label;
  p["type"] = paramTypeName(spec.type);
  p["default"] = nlohmann::ordered_json(paramValueToJson(spec, spec.def));
  if (spec.type == ParamType::Enum) {
    p["min"] = spec.choices.front();
    p["max"] = spec.choices.back();
    p["choices"] = spec.choices;
  } else if (spec.type == ParamType::Bool) {
    p["min"] = false;
    p["max"] = true;
  } else if (spec.type == ParamType::Int) {
    p["min"] = static_cast<long long>(spec.min);
    p["max"] = static_cast<long long>(spec.max);
  } else {
    p["min"] = spec.min;
    p["max"] = spec.max;
  }
  p["scale"] = spec.scale == ParamScale::Log ? "log" : "linear";
  p["unit"] = spec.unit;
  p["help"] = spec.help;
  p["needs_recompile"] = (spec.flags & kParamRecompile) != 0;
  p["needs_reallocation"] = (spec.flags & kParamRealloc) != 0;
  return p;
}

} // namespace rtlab
