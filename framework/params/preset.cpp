#include "params/preset.h"

#include "params/param_set.h"
#include "util/atomic_file.h"
#include "util/error.h"

#include <filesystem>

namespace rtlab {

Preset loadPreset(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) inputError("cannot read preset '" + path + "': it is a directory");
  const std::string text = readFileOrThrow(path, "preset");
  // ordered_json keeps the file's key order (nlohmann::json sorts keys), so params apply and
  // report errors in the order the file lists them.
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) inputError("preset '" + path + "' is not valid JSON");
  if (!j.is_object()) inputError("preset '" + path + "' must be a JSON object");
  Preset p;
  for (const auto& [name, value] : j.items()) {
    if (name == "schema") {
      // get<long long>: get<int> would wrap 4294967297 to 1.
      if (!value.is_number_integer() || value.get<long long>() != 1)
        inputError("preset '" + path + "' has unsupported schema " + value.dump() + " (expected 1)");
    } else if (name == "scene") {
      if (!value.is_string()) inputError("preset '" + path + "': \"scene\" must be a string");
      p.scene = value.get<std::string>();
    } else if (name == "techniques") {
      if (!value.is_array()) inputError("preset '" + path + "': \"techniques\" must be an array of strings");
      std::vector<std::string> ids;
      for (const auto& t : value) {
        if (!t.is_string()) inputError("preset '" + path + "': \"techniques\" must be an array of strings");
        ids.push_back(t.get<std::string>());
      }
      p.techniques = ids;
    } else if (name == "params") {
      if (!value.is_object()) inputError("preset '" + path + "': \"params\" must be an object");
      for (const auto& [key, v] : value.items()) p.params.emplace_back(key, nlohmann::json(v));
    } else {
      inputError("preset '" + path + "' has unknown field \"" + name + "\"");
    }
  }
  return p;
}

void applyPreset(const Preset& preset, ParamSet& params, const std::string& path) {
  for (const auto& [key, value] : preset.params) {
    try {
      params.setJson(key, value);
    } catch (const Error& e) {
      throw Error(e.code(), std::string(e.what()) + " in preset '" + path + "'");
    }
  }
}

void savePreset(const std::string& path, const std::string& scene, const std::vector<std::string>& techniques,
                const ParamSet& params) {
  nlohmann::ordered_json j;
  j["schema"] = 1;
  j["scene"] = scene;
  j["techniques"] = techniques;
  nlohmann::ordered_json p = nlohmann::ordered_json::object();
  for (const auto& spec : params.specs()) p[spec.key] = paramValueToJson(spec, params.value(spec.key));
  j["params"] = p;
  writeTextAtomically(path, j.dump(2) + "\n");
}

} // namespace rtlab
