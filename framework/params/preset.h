// Preset files (docs/contract.md): {"schema": 1, "scene": "...", "techniques": ["pcss", ...],
// "params": {"KEY": value}}. All fields optional.
#pragma once
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rtlab {

class ParamSet;

struct Preset {
  std::optional<std::string> scene;
  std::optional<std::vector<std::string>> techniques;
  std::vector<std::pair<std::string, nlohmann::json>> params; // in file order
};

// Missing, unreadable, not JSON, wrong schema or wrong field types: Error(Input) naming the file.
Preset loadPreset(const std::string& path);
// Applies params to the set; an unknown key or bad value is Error(Usage) naming the key and file.
void applyPreset(const Preset& preset, ParamSet& params, const std::string& path);
// Writes atomically; Error(Output) on failure.
void savePreset(const std::string& path, const std::string& scene, const std::vector<std::string>& techniques,
                const ParamSet& params);

} // namespace rtlab
