// The single declaration of a parameter (docs/architecture.md "Parameters"). From one ParamSpec come the UI
// slider, `--set key=value`, JSON presets, `rtlab list --json`, sweep axes and the extremes tests.
#pragma once
#include <glm/glm.hpp>
#include <nlohmann/json_fwd.hpp>

#include <array>
#include <string>
#include <vector>

namespace rtlab {

enum class ParamType { Float, Int, Bool, Enum, Vec3, Color };
enum class ParamScale { Linear, Log };

// What changing the parameter costs the renderer.
enum ParamFlag : unsigned {
  kParamUniform = 0,       // a uniform: free to change every frame
  kParamRecompile = 1u << 0, // changes shader defines
  kParamRealloc = 1u << 1,   // changes a resource's size or format
};

// A value of any ParamType. Scalars (float, int, bool as 0/1, enum as choice index) live in v[0].
struct ParamValue {
  std::array<double, 3> v{0, 0, 0};
  static ParamValue scalar(double x) { return ParamValue{{x, 0, 0}}; }
  static ParamValue vec3(const glm::vec3& x) { return ParamValue{{x.x, x.y, x.z}}; }
  bool operator==(const ParamValue&) const = default;
};

struct ParamSpec {
  std::string key;   // "<technique>.<name>", "<stage>.<name>", "tonemap.<name>", "light<N>.<name>", "camera.<name>"
  std::string label; // UI label
  ParamType type = ParamType::Float;
  ParamValue def;
  double min = 0.0, max = 1.0; // per component for vec3/color; choice index range for enums
  ParamScale scale = ParamScale::Linear;
  std::string unit;
  std::string help;
  std::vector<std::string> choices; // enums
  unsigned flags = kParamUniform;

  // Fluent constructors: ParamSpec::real("pcf.radius", "Radius", 1.5, 0, 8).withUnit("texels").withHelp("...")
  static ParamSpec real(std::string key, std::string label, double def, double min, double max);
  static ParamSpec integer(std::string key, std::string label, int def, int min, int max);
  static ParamSpec boolean(std::string key, std::string label, bool def);
  static ParamSpec choice(std::string key, std::string label, std::vector<std::string> choices, int def);
  static ParamSpec vector3(std::string key, std::string label, glm::vec3 def, double min, double max);
  static ParamSpec color(std::string key, std::string label, glm::vec3 def, double min = 0.0, double max = 1.0);

  ParamSpec& withUnit(std::string u) { unit = std::move(u); return *this; }
  ParamSpec& withHelp(std::string h) { help = std::move(h); return *this; }
  ParamSpec& logScale() { scale = ParamScale::Log; return *this; }
  ParamSpec& withFlags(unsigned f) { flags |= f; return *this; }

  bool isNumeric() const { return type == ParamType::Float || type == ParamType::Int; }
  int components() const { return (type == ParamType::Vec3 || type == ParamType::Color) ? 3 : 1; }
};

const char* paramTypeName(ParamType type);

// Parses text by the spec's type (docs/contract.md "Keys and values"): decimal floats/ints, bool
// true|false|1|0|on|off, enum by name, vec3/color as x,y,z. Checks the range. Throws Error(Usage)
// naming the key and its range/choices.
ParamValue parseParamValue(const ParamSpec& spec, const std::string& text);
// The same from JSON (numbers, booleans, enum strings, arrays of 3 numbers).
ParamValue paramValueFromJson(const ParamSpec& spec, const nlohmann::json& value);
// Throws Error(Usage) if value is outside [min, max] (any component) or not an integer for ints.
void checkParamRange(const ParamSpec& spec, const ParamValue& value);

std::string formatParamValue(const ParamSpec& spec, const ParamValue& value); // CLI syntax
nlohmann::json paramValueToJson(const ParamSpec& spec, const ParamValue& value);
// P of docs/contract.md: key, type, default, min, max, scale, unit, choices (enums), help.
nlohmann::ordered_json paramSpecToJson(const ParamSpec& spec);
std::string describeRange(const ParamSpec& spec); // "[0, 0.05]" or "one of: a, b"

} // namespace rtlab
