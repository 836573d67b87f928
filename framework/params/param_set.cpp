#include "params/param_set.h"

#include "util/error.h"
#include "util/suggest.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace rtlab {

void ParamSet::declare(const ParamSpec& spec) {
  if (has(spec.key)) throw Error(ExitCode::Internal, "parameter '" + spec.key + "' declared twice");
  if (spec.type == ParamType::Enum && spec.choices.empty())
    throw Error(ExitCode::Internal, "enum parameter '" + spec.key + "' has no choices");
  if (!(spec.min <= spec.max))
    throw Error(ExitCode::Internal, "parameter '" + spec.key + "' has min > max (" + describeRange(spec) + ")");
  try {
    checkParamRange(spec, spec.def);
  } catch (const Error& e) {
    // A default outside its own range is a programming error, not the user's (exit 1, not 2).
    throw Error(ExitCode::Internal, std::string("default of parameter declaration: ") + e.what());
  }
  m_index[spec.key] = m_specs.size();
  m_specs.push_back(spec);
  m_values.push_back(spec.def);
  ++m_revision;
}

void ParamSet::declare(const std::vector<ParamSpec>& specs) {
  for (const auto& s : specs) declare(s);
}

std::size_t ParamSet::indexOf(const std::string& key) const {
  auto it = m_index.find(key);
  if (it != m_index.end()) return it->second;
  std::vector<std::string> keys;
  for (const auto& s : m_specs) keys.push_back(s.key);
  usageError("unknown key '" + key + "'" + didYouMean(key, keys, " (see 'rtlab list')"));
}

const ParamSpec& ParamSet::spec(const std::string& key) const { return m_specs[indexOf(key)]; }

void ParamSet::set(const std::string& key, const ParamValue& value) {
  const std::size_t i = indexOf(key);
  checkParamRange(m_specs[i], value);
  if (!(m_values[i] == value)) {
    m_values[i] = value;
    ++m_revision;
  }
}

void ParamSet::setText(const std::string& key, const std::string& text) {
  const std::size_t i = indexOf(key);
  set(key, parseParamValue(m_specs[i], text));
}

void ParamSet::setAssignment(const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    usageError("expected KEY=VALUE after --set, got '" + assignment + "'");
  setText(assignment.substr(0, eq), assignment.substr(eq + 1));
}

void ParamSet::setJson(const std::string& key, const nlohmann::json& value) {
  const std::size_t i = indexOf(key);
  set(key, paramValueFromJson(m_specs[i], value));
}

void ParamSet::reset(const std::string& key) { set(key, spec(key).def); }

const ParamValue& ParamSet::value(const std::string& key) const { return m_values[indexOf(key)]; }

float ParamSet::getFloat(const std::string& key) const { return float(value(key).v[0]); }
int ParamSet::getInt(const std::string& key) const { return int(value(key).v[0]); }
bool ParamSet::getBool(const std::string& key) const { return value(key).v[0] != 0.0; }
int ParamSet::getEnum(const std::string& key) const { return int(value(key).v[0]); }

const std::string& ParamSet::getEnumName(const std::string& key) const {
  const std::size_t i = indexOf(key);
  return m_specs[i].choices.at(std::size_t(m_values[i].v[0]));
}

glm::vec3 ParamSet::getVec3(const std::string& key) const {
  const auto& v = value(key).v;
  return glm::vec3(float(v[0]), float(v[1]), float(v[2]));
}

nlohmann::json ParamSet::toJson(const std::vector<std::string>& prefixes) const {
  nlohmann::json out = nlohmann::json::object();
  for (std::size_t i = 0; i < m_specs.size(); ++i) {
    const auto& key = m_specs[i].key;
    bool match = prefixes.empty();
    for (const auto& p : prefixes) match = match || key.rfind(p, 0) == 0;
    if (match) out[key] = paramValueToJson(m_specs[i], m_values[i]);
  }
  return out;
}

} // namespace rtlab
