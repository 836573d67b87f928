// The resolved values of every declared parameter, in declaration order.
#pragma once
#include "params/param_spec.h"

#include <map>
#include <string>
#include <vector>

namespace rtlab {

class ParamSet {
public:
  // Declares a parameter with its default value. Declaring a key twice is an internal error.
  void declare(const ParamSpec& spec);
  void declare(const std::vector<ParamSpec>& specs);

  bool has(const std::string& key) const { return m_index.count(key) != 0; }
  // Throws Error(Usage) "unknown key 'x'" (with the nearest known key when one is close).
  const ParamSpec& spec(const std::string& key) const;
  const std::vector<ParamSpec>& specs() const { return m_specs; }

  // Setters validate (range, syntax) and throw Error(Usage) naming the key.
  void set(const std::string& key, const ParamValue& value);
  void setText(const std::string& key, const std::string& text);             // --set KEY=VALUE
  void setAssignment(const std::string& assignment);                         // "KEY=VALUE"
  void setJson(const std::string& key, const nlohmann::json& value);         // presets
  void reset(const std::string& key);

  const ParamValue& value(const std::string& key) const;
  float getFloat(const std::string& key) const;
  int getInt(const std::string& key) const;
  bool getBool(const std::string& key) const;
  int getEnum(const std::string& key) const;
  const std::string& getEnumName(const std::string& key) const;
  glm::vec3 getVec3(const std::string& key) const;

  // Bumped whenever a value changes: lets caches notice edits cheaply.
  unsigned long revision() const { return m_revision; }

  // {KEY: value} for every parameter whose key starts with one of the prefixes (all when empty).
  nlohmann::json toJson(const std::vector<std::string>& prefixes = {}) const;

private:
  std::size_t indexOf(const std::string& key) const;
  std::vector<ParamSpec> m_specs;
  std::vector<ParamValue> m_values;
  std::map<std::string, std::size_t> m_index;
  unsigned long m_revision = 0;
};

} // namespace rtlab
