// Script validation against the frame's registry and parameters, before the first frame: every
// technique id, key and value the script will use is checked the way `-t` and `--set` check
// them (frame/selection.cpp, params/param_set.cpp), on a copy of the parameters so that values
// apply in order.
#include "frame/registry.h"
#include "frame/stages.h"
#include "params/param_set.h"
#include "params/preset.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "viewer/json_fields.h"
#include "viewer/script.h"
#include "viewer/view_fields.h"

#include <cstdio>
#include <filesystem>
#include <set>

namespace rtlab {
namespace {

using nlohmann::json;

void checkTechniqueAction(const json& args, const TechniqueRegistry& registry) {
  const std::string stage = args.at("stage").get<std::string>();
  const std::string id = args.at("id").get<std::string>();
  if (!findStage(stage)) {
    std::string list;
    for (const auto& s : stages())
      list += (list.empty() ? "" : ", ") + s.id;
    usageError("unknown stage '" + stage + "' (known: " + list + ")");
  }
  if (id == "off" || id == "none") return; // "none" as `-t none` spells it
  const TechniqueEntry& entry = registry.get(id); // Error(Usage) listing the known ids
  if (entry.info.stage != stage)
    usageError("technique '" + id + "' belongs to stage '" + entry.info.stage + "', not '" + stage + "'");
}

void checkCameraAction(const json& args, ParamSet& params) {
  static const std::pair<const char*, const char*> fields[] = {
      {"position", "camera.position"}, {"target", "camera.target"}, {"fov", "camera.fov"}};
  for (const auto& [field, key] : fields) {
    if (!args.contains(field)) continue;
    if (params.has(key))
      params.setJson(key, args.at(field));
    else if (std::string(field) == "fov" &&
             !(args.at(field).get<double>() >= 1.0 && args.at(field).get<double>() <= 170.0))
      usageError("\"fov\" = " + args.at(field).dump() + " is out of range [1, 170]");
  }
}

void checkLoadPreset(const std::string& path, ParamSet& params, const TechniqueRegistry& registry) {
  const Preset preset = loadPreset(path); // Error(Input) naming the file
  if (preset.techniques)
    for (const auto& id : *preset.techniques)
      if (id != "none") registry.get(id);
  applyPreset(preset, params, path);
}

void checkRampAction(const json& args, ParamSet& params) {
  const std::string key = args.at("key").get<std::string>();
  const ParamSpec& spec = params.spec(key); // Error(Usage) for an unknown key
  if (!spec.isNumeric())
    usageError("ramp: '" + key + "' is a " + paramTypeName(spec.type) + " key; a ramp needs a float or int key");
  params.setJson(key, args.at("from"));
  params.setJson(key, args.at("to")); // the value the ramp ends at
}

void checkRecordAction(const json& args) {
  namespace fs = std::filesystem;
  const std::string dir = args.at("dir").get<std::string>();
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) outputError("record: directory '" + dir + "' does not exist");
  checkOutputPath(recordedFramePath(dir, 0));
}

} // namespace

std::string recordedFramePath(const std::string& dir, long n) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05ld.png", n);
  return (std::filesystem::path(dir) / name).string();
}

void validateScript(const std::vector<ScriptAction>& script, const ParamSet& params,
                    const TechniqueRegistry& registry) {
  ParamSet copy = params;
  std::set<std::string> savedPresets; // written by an earlier "save_preset": checked when saved
  bool recording = false;
  for (const ScriptAction& a : script) {
    checkScriptAction(a); // so every field read below exists with its type
    try {
      const json& args = a.args;
      if (a.action == "technique") {
        checkTechniqueAction(args, registry);
      } else if (a.action == "set") {
        copy.setJson(args.at("key").get<std::string>(), args.at("value"));
      } else if (a.action == "reset") {
        copy.reset(args.at("key").get<std::string>());
      } else if (a.action == "camera") {
        checkCameraAction(args, copy);
      } else if (a.action == "view" && args.contains("aov")) {
        checkViewAov(args.at("aov").get<std::string>(), registry);
      } else if (a.action == "load_preset") {
        const std::string file = args.at("file").get<std::string>();
        if (!savedPresets.count(file)) checkLoadPreset(file, copy, registry);
      } else if (a.action == "save_preset") {
        checkOutputPath(args.at("file").get<std::string>());
        savedPresets.insert(args.at("file").get<std::string>());
      } else if (a.action == "ramp") {
        checkRampAction(args, copy);
      } else if (a.action == "record") {
        if (recording) usageError("a recording is already running (end it with \"stop\" first)");
        checkRecordAction(args);
        recording = true;
      } else if (a.action == "stop") {
        if (!recording) usageError("no recording to stop (start one with \"record\")");
        recording = false;
      } else if (a.action == "screenshot" || a.action == "report") {
        checkOutputPath(args.at("file").get<std::string>());
      }
    } catch (const Error& e) {
      throw Error(e.code(), a.where() + ": " + e.what());
    }
  }
}

void validateScriptBookmarks(const std::vector<ScriptAction>& script, std::size_t bookmarkCount) {
  for (const ScriptAction& a : script) {
    if (a.action != "bookmark") continue;
    checkScriptAction(a);
    const long long index = a.args.at("index").get<long long>();
    if (index < 0 || static_cast<unsigned long long>(index) >= bookmarkCount)
      usageError(a.where() + ": bookmark " + std::to_string(index) + " does not exist (" +
                 (bookmarkCount == 0 ? std::string("no bookmarks were loaded; see --bookmarks")
                                     : "there are " + std::to_string(bookmarkCount) + ", numbered from 0") +
                 ")");
  }
}

} // namespace rtlab
