#include "viewer/view_fields.h"

#include "util/error.h"
#include "viewer/json_fields.h"

namespace rtlab {

void checkViewFields(const nlohmann::json& object, const std::string& where) {
  optionalString(object, "aov", where);
  if (auto mode = optionalString(object, "mode", where)) requireChoice(*mode, {"full", "pip", "off"}, "mode", where);
  const auto lo = optionalNumber(object, "min", where);
  const auto hi = optionalNumber(object, "max", where);
  optionalBool(object, "false_color", where);
  if (lo && hi && !(*lo < *hi))
    usageError(where + ": \"min\" (" + formatNumber(*lo) + ") must be less than \"max\" (" +
               formatNumber(*hi) + ")");
}

void checkCompareFields(const nlohmann::json& object, const std::string& where) {
  if (auto mode = optionalString(object, "mode", where))
    requireChoice(*mode, {"reference", "snapshot", "difference", "off"}, "mode", where);
  if (auto divider = optionalNumber(object, "divider", where)) requireRange(*divider, 0.0, 1.0, "divider", where);
}

} // namespace rtlab
