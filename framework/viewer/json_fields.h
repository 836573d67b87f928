// Typed access to the fields of a JSON object, shared by the viewer's script and bookmark
// parsers. Every failure is Error(Input) (exit 3: the file is invalid) with a one-line message
// that starts with `where` (e.g. "script 'demo.json' action 3 (\"wait\")") and names the field.
// Range and choice checks, which are the user's values rather than the file's shape, are
// Error(Usage) (exit 2), as for `--set`.
#pragma once
#include <nlohmann/json.hpp>

#include <glm/glm.hpp>

#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

namespace rtlab {

// Parses JSON text; Error(Input) "<name> is not valid JSON: <parser's reason>" (syntax errors
// with line and column, numbers too large for a double).
nlohmann::json parseJsonText(const std::string& text, const std::string& name);
// Error(Input) unless `value` is an object.
void requireObject(const nlohmann::json& value, const std::string& where);
// Error(Input) naming the first field of `object` not in `allowed`, and listing `allowed`.
void rejectUnknownFields(const nlohmann::json& object, const std::vector<const char*>& allowed,
                         const std::string& where);

// Required fields: Error(Input) when missing or of the wrong JSON type.
std::string requireString(const nlohmann::json& object, const char* field, const std::string& where);
double requireNumber(const nlohmann::json& object, const char* field, const std::string& where);
long long requireInteger(const nlohmann::json& object, const char* field, const std::string& where);
bool requireBool(const nlohmann::json& object, const char* field, const std::string& where);
glm::vec3 requireVec3(const nlohmann::json& object, const char* field, const std::string& where);

// Optional fields: empty when absent; Error(Input) when present with the wrong JSON type.
std::optional<std::string> optionalString(const nlohmann::json& object, const char* field, const std::string& where);
std::optional<double> optionalNumber(const nlohmann::json& object, const char* field, const std::string& where);
std::optional<long long> optionalInteger(const nlohmann::json& object, const char* field, const std::string& where);
std::optional<bool> optionalBool(const nlohmann::json& object, const char* field, const std::string& where);
std::optional<glm::vec3> optionalVec3(const nlohmann::json& object, const char* field, const std::string& where);
std::optional<std::vector<std::string>> optionalStringList(const nlohmann::json& object, const char* field,
                                                           const std::string& where);

// A parameter value as presets write it: a number, a boolean, a string (enums) or an array of
// numbers (vec3, color). Error(Input) for anything else; the key decides the rest (ParamSet).
void requireParamValueShape(const nlohmann::json& value, const std::string& what, const std::string& where);

// Error(Usage) unless `value` is one of `choices` ("\"mode\" must be one of: full, pip, off").
void requireChoice(const std::string& value, std::initializer_list<const char*> choices, const char* field,
                   const std::string& where);
// Error(Usage) unless lo <= value <= hi (both inclusive).
void requireRange(double value, double lo, double hi, const char* field, const std::string& where);

// The shortest decimal that reads back as the same float: 0.1f is written 0.1, not
// 0.10000000149011612, and still round-trips exactly.
double jsonNumberFromFloat(float value);
// The shortest decimal of a number, for messages: 1, 0.25, 1e+30.
std::string shortestDecimal(double value);
nlohmann::json jsonFromVec3(const glm::vec3& value);

} // namespace rtlab
