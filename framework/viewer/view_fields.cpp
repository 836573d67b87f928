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

} // namespace rtlab
