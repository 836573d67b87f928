// Script parsing: the JSON shape of every action (docs/viewer-scripts.md). One table lists each
// action's fields; a per-action check reads them with the typed getters of json_fields.h, so a
// field of the wrong type is exit 3 and a value out of range exit 2, before anything runs.
#include "viewer/script.h"

#include "image/image.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "viewer/json_fields.h"
#include "viewer/view_fields.h"

#include <algorithm>
#include <filesystem>

namespace rtlab {
namespace {

using nlohmann::json;
using Check = void (*)(const json& args, const std::string& where);

struct ActionSpec {
  const char* name;
  std::vector<const char*> fields; // besides "action"
  Check check;
};

void atLeastOne(const json& args, const std::vector<const char*>& fields, const std::string& where) {
  for (const char* f : fields)
    if (args.contains(f)) return;
  std::string list;
  for (const char* f : fields)
    list += std::string(list.empty() ? "" : ", ") + "\"" + f + "\"";
  inputError(where + ": needs at least one of " + list);
}

void nonNegative(long long value, const char* field, const std::string& where) {
  if (value < 0) usageError(where + ": \"" + field + "\" must be >= 0, got " + std::to_string(value));
}

std::string requireFile(const json& args, const std::string& where) {
  std::string file = requireString(args, "file", where);
  if (file.empty()) usageError(where + ": \"file\" must not be empty");
  return file;
}

void checkTechnique(const json& a, const std::string& w) {
  requireString(a, "stage", w);
  requireString(a, "id", w);
}
void checkSet(const json& a, const std::string& w) {
  requireString(a, "key", w);
  if (!a.contains("value")) inputError(w + ": missing field \"value\"");
  requireParamValueShape(a["value"], "\"value\"", w);
}
void checkReset(const json& a, const std::string& w) {
  requireString(a, "key", w);
}
void checkCamera(const json& a, const std::string& w) {
  atLeastOne(a, {"position", "target", "fov"}, w);
  const auto position = optionalVec3(a, "position", w);
  const auto target = optionalVec3(a, "target", w);
  optionalNumber(a, "fov", w);
  if (position && target && glm::length(*target - *position) < 1e-6f)
    usageError(w + ": \"target\" must differ from \"position\"");
}
void checkOrbit(const json& a, const std::string& w) {
  atLeastOne(a, {"yaw", "pitch"}, w);
  optionalNumber(a, "yaw", w);
  optionalNumber(a, "pitch", w);
}
void checkView(const json& a, const std::string& w) {
  atLeastOne(a, {"aov", "mode", "min", "max", "false_color"}, w);
  checkViewFields(a, w);
}
void checkCompare(const json& a, const std::string& w) {
  atLeastOne(a, {"mode", "divider"}, w);
  checkCompareFields(a, w);
}
void checkNothing(const json&, const std::string&) {}
void checkWait(const json& a, const std::string& w) {
  nonNegative(requireInteger(a, "frames", w), "frames", w);
}
void checkWaitSamples(const json& a, const std::string& w) {
  nonNegative(requireInteger(a, "samples", w), "samples", w);
  if (auto t = optionalNumber(a, "timeout_s", w); t && !(*t > 0))
    usageError(w + ": \"timeout_s\" must be > 0, got " + shortestDecimal(*t));
}
void checkScreenshot(const json& a, const std::string& w) {
  const std::string file = requireFile(a, w);
  requirePngPath(file, w + ": \"file\"");
}
void checkFile(const json& a, const std::string& w) {
  requireFile(a, w);
}
void checkRenderScale(const json& a, const std::string& w) {
  requireRange(requireNumber(a, "value", w), kRenderScaleMin, kRenderScaleMax, "value", w);
}
void checkLecture(const json& a, const std::string& w) {
  requireBool(a, "on", w);
}
void checkBookmark(const json& a, const std::string& w) {
  nonNegative(requireInteger(a, "index", w), "index", w);
}
void checkPanel(const json& a, const std::string& w) {
  requireBool(a, "on", w);
}
void checkSection(const json& a, const std::string& w) {
  const std::string name = requireString(a, "name", w);
  optionalBool(a, "open", w);
  checkSectionName(name, w);
}
void checkRamp(const json& a, const std::string& w) {
  requireString(a, "key", w);
  requireNumber(a, "from", w);
  requireNumber(a, "to", w);
  const long long frames = requireInteger(a, "frames", w);
  if (frames < 1) usageError(w + ": \"frames\" must be >= 1, got " + std::to_string(frames));
}
void checkRecord(const json& a, const std::string& w) {
  if (requireString(a, "dir", w).empty()) usageError(w + ": \"dir\" must not be empty");
}

const std::vector<ActionSpec>& actionSpecs() {
  static const std::vector<ActionSpec> specs = {
      {"technique", {"stage", "id"}, checkTechnique},
      {"set", {"key", "value"}, checkSet},
      {"reset", {"key"}, checkReset},
      {"camera", {"position", "target", "fov"}, checkCamera},
      {"orbit", {"yaw", "pitch"}, checkOrbit},
      {"view", {"aov", "mode", "min", "max", "false_color"}, checkView},
      {"compare", {"mode", "divider"}, checkCompare},
      {"snapshot", {}, checkNothing},
      {"wait", {"frames"}, checkWait},
      {"wait_samples", {"samples", "timeout_s"}, checkWaitSamples},
      {"screenshot", {"file"}, checkScreenshot},
      {"save_preset", {"file"}, checkFile},
      {"load_preset", {"file"}, checkFile},
      {"report", {"file"}, checkFile},
      {"render_scale", {"value"}, checkRenderScale},
      {"lecture", {"on"}, checkLecture},
      {"bookmark", {"index"}, checkBookmark},
      {"panel", {"on"}, checkPanel},
      {"section", {"name", "open"}, checkSection},
      {"ramp", {"key", "from", "to", "frames"}, checkRamp},
      {"record", {"dir"}, checkRecord},
      {"stop", {}, checkNothing},
      {"quit", {}, checkNothing},
  };
  return specs;
}

std::string scriptName(const std::string& source) {
  return "script '" + source + "'";
}

} // namespace

std::string ScriptAction::where() const {
  return scriptName(source) + " action " + std::to_string(index) + " (\"" + action + "\")";
}

const std::vector<std::string>& scriptActionNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const auto& s : actionSpecs())
      out.push_back(s.name);
    return out;
  }();
  return names;
}

void checkScriptAction(const ScriptAction& a) {
  const std::string at = scriptName(a.source) + " action " + std::to_string(a.index);
  requireObject(a.args, at);
  const auto& specs = actionSpecs();
  auto spec = std::find_if(specs.begin(), specs.end(), [&](const ActionSpec& s) { return a.action == s.name; });
  if (spec == specs.end()) {
    std::string list;
    for (const auto& s : specs)
      list += std::string(list.empty() ? "" : ", ") + s.name;
    inputError(at + ": unknown action \"" + a.action + "\" (known: " + list + ")");
  }
  json fields = a.args;
  fields.erase("action");
  rejectUnknownFields(fields, spec->fields, a.where());
  spec->check(a.args, a.where());
}

std::vector<ScriptAction> parseScript(const std::string& text, const std::string& sourceName) {
  const std::string name = scriptName(sourceName);
  const json j = parseJsonText(text, name);
  if (!j.is_array()) inputError(name + " must be a JSON list of actions, got " + std::string(j.type_name()));
  std::vector<ScriptAction> script;
  for (std::size_t i = 0; i < j.size(); ++i) {
    ScriptAction a;
    a.index = i;
    a.source = sourceName;
    a.args = j[i];
    const std::string at = name + " action " + std::to_string(i);
    requireObject(a.args, at);
    a.action = requireString(a.args, "action", at);
    checkScriptAction(a);
    script.push_back(std::move(a));
  }
  return script;
}

std::vector<ScriptAction> loadScript(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) inputError("cannot read script '" + path + "': it is a directory");
  return parseScript(readFileOrThrow(path, "script"), path);
}

} // namespace rtlab
