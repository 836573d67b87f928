#include "viewer/view_fields.h"

#include "frame/aovs.h"
#include "frame/registry.h"
#include "util/error.h"
#include "util/suggest.h"
#include "viewer/json_fields.h"

namespace rtlab {

void checkViewFields(const nlohmann::json& object, const std::string& where) {
  optionalString(object, "aov", where);
  if (auto mode = optionalString(object, "mode", where)) requireChoice(*mode, {"full", "pip", "off"}, "mode", where);
  const auto lo = optionalNumber(object, "min", where);
  const auto hi = optionalNumber(object, "max", where);
  optionalBool(object, "false_color", where);
  if (lo && hi && !(*lo < *hi))
    usageError(where + ": \"min\" (" + shortestDecimal(*lo) + ") must be less than \"max\" (" + shortestDecimal(*hi) +
               ")");
}

void checkCompareFields(const nlohmann::json& object, const std::string& where) {
  if (auto mode = optionalString(object, "mode", where))
    requireChoice(*mode, {"reference", "snapshot", "difference", "off"}, "mode", where);
  if (auto divider = optionalNumber(object, "divider", where)) requireRange(*divider, 0.0, 1.0, "divider", where);
}

void checkViewAov(const std::string& aov, const TechniqueRegistry& registry) {
  if (isBuiltinAov(aov)) return;
  for (const auto& e : registry.entries())
    for (const auto& v : e.info.debugViews)
      if (v.name == aov) return;
  usageError("unknown AOV '" + aov + "'" + didYouMean(aov, knownAovNames(registry), " (see 'rtlab list')"));
}

const std::vector<std::string>& viewerSectionNames() {
  static const std::vector<std::string> names = {"Speaker notes", "Scene",      "Techniques", "Lights",
                                                 "Tone mapping",  "Debug view", "Compare",    "Timings"};
  return names;
}

void checkSectionName(const std::string& name, const std::string& where) {
  for (const auto& known : viewerSectionNames())
    if (name == known) return;
  std::string list;
  for (const auto& known : viewerSectionNames())
    list += (list.empty() ? "\"" : ", \"") + known + "\"";
  usageError(where + ": unknown section \"" + name + "\" (known: " + list + ")");
}

void checkSectionsField(const nlohmann::json& object, const std::string& where) {
  requireObject(object, where);
  for (const auto& [name, open] : object.items()) {
    if (!open.is_boolean())
      inputError(where + ": \"" + name + "\" must be a boolean (open or closed), got " + std::string(open.type_name()));
    checkSectionName(name, where);
  }
}

} // namespace rtlab
