// One ImGui control per parameter, drawn from its ParamSpec alone (docs/architecture.md "Parameters"): a
// slider for float and int (logarithmic where the spec says so, the unit in the format), a
// checkbox for bool, a combo for enums, three fields for vec3 and a color editor for colors; a
// "(?)" marker with the help text and the range; a reset button when the value is not the default.
// Nothing here knows a technique.
#pragma once
#include "params/param_spec.h"

#include <string>
#include <vector>

namespace rtlab {

class ParamSet;

// Draws the control for `spec` showing `value`. Returns true if the user changed it (the new,
// in-range value is in `value`) or pressed reset (`value` is the default).
bool drawParamControl(const ParamSpec& spec, ParamValue& value);
// "(?)"; true while the mouse is over it (the caller then shows its text with helpTooltip, so a
// text that must be built is built only then, not every frame).
bool helpMarkerHovered();
void helpTooltip(const char* text);
// "(?)" with a tooltip.
inline void helpMarker(const char* text) {
  if (helpMarkerHovered()) helpTooltip(text);
}

// True when `label` and `after` more pixels fit on the current line; else wrappedLabel draws it
// wrapped at the window's edge (labels are never cut).
bool labelFits(const char* label, float after = 0.0f);
void wrappedLabel(const char* label);

// An edit made in a panel, applied by the caller through the viewer's actions.
struct ParamEdit {
  std::string key;
  ParamValue value;
};
// Controls for every key of `params` that starts with `prefix`; edits are appended to `edits`.
void drawParamGroup(const ParamSet& params, const std::string& prefix, std::vector<ParamEdit>& edits);

} // namespace rtlab
