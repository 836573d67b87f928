// The debug-view and A/B compare settings that both a script action ("view", "compare") and a
// bookmark ("view": {...}, "compare": {...}) carry, checked the same way in both: JSON types are
// Error(Input), a mode outside its choices or a value out of range Error(Usage).
#pragma once
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace rtlab {

class TechniqueRegistry;

// Optional fields "aov" (string), "mode" ("full" | "pip" | "off"), "min", "max" (numbers,
// min < max when both are given), "false_color" (boolean). Unknown fields are the caller's check.
void checkViewFields(const nlohmann::json& object, const std::string& where);
// Optional fields "mode" ("reference" | "snapshot" | "difference" | "off") and "divider"
// (number in [0, 1], the split's position from the left edge).
void checkCompareFields(const nlohmann::json& object, const std::string& where);

// Error(Usage) "unknown AOV 'x'" unless `aov` is a built-in AOV or a debug view of any registered
// technique (whether that technique is active is known only when the view is applied).
void checkViewAov(const std::string& aov, const TechniqueRegistry& registry);

// The panel's section headers, in drawing order ("Scene", "Techniques", ..., "Speaker notes"):
// the names a script's "section" action and a bookmark's "sections" open or close.
const std::vector<std::string>& viewerSectionNames();
// Error(Usage) naming the known sections unless `name` is one of them.
void checkSectionName(const std::string& name, const std::string& where);
// A bookmark's "sections" object {NAME: boolean}: Error(Input) for a non-boolean, Error(Usage)
// for an unknown name.
void checkSectionsField(const nlohmann::json& object, const std::string& where);

} // namespace rtlab
