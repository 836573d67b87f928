#include "ui/param_widgets.h"

#include "params/param_set.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace rtlab {
namespace {

std::string tooltipText(const ParamSpec& spec) {
  std::string text = spec.help.empty() ? spec.label : spec.help;
  text += "\nkey: " + spec.key + "\nrange: " + describeRange(spec);
  if (!spec.unit.empty()) text += " " + spec.unit;
  if (spec.scale == ParamScale::Log) text += " (log scale)";
  if (spec.flags & kParamRecompile) text += "\nchanging it recompiles shaders";
  if (spec.flags & kParamRealloc) text += "\nchanging it reallocates a resource";
  return text;
}

std::string numberFormat(const ParamSpec& spec) {
  std::string f = spec.type == ParamType::Int ? "%d" : "%.4g";
  if (spec.unit.empty()) return f;
  f += ' ';
  for (char c : spec.unit)
    f += c == '%' ? std::string("%%") : std::string(1, c); // '%' is a directive
  return f;
}

// The widgets work in float: a slider at its end gives float(max), which may lie just outside the
// double range; that rounding is undone. A value typed beyond the range (Ctrl+click) is passed on
// as typed, so the action rejects it with the key's range in the status line (no silent clamp).
double fromWidget(double v, const ParamSpec& spec) {
  if (v > spec.max && float(v) == float(spec.max)) return spec.max;
  if (v < spec.min && float(v) == float(spec.min)) return spec.min;
  return v;
}

bool drawValue(const ParamSpec& spec, ParamValue& value, const char* id) {
  const ImGuiSliderFlags flags = spec.scale == ParamScale::Log ? ImGuiSliderFlags_Logarithmic : 0;
  switch (spec.type) {
  case ParamType::Float: {
    float v = float(value.v[0]);
    const bool changed =
        ImGui::SliderFloat(id, &v, float(spec.min), float(spec.max), numberFormat(spec).c_str(), flags);
    if (changed) value.v[0] = fromWidget(double(v), spec);
    return changed;
  }
  case ParamType::Int: {
    int v = int(value.v[0]);
    const bool changed = ImGui::SliderInt(id, &v, int(spec.min), int(spec.max), numberFormat(spec).c_str(), flags);
    if (changed) value.v[0] = fromWidget(double(v), spec);
    return changed;
  }
  case ParamType::Bool: {
    bool v = value.v[0] != 0.0;
    const bool changed = ImGui::Checkbox(id, &v);
    if (changed) value.v[0] = v ? 1.0 : 0.0;
    return changed;
  }
  case ParamType::Enum: {
    int v = int(value.v[0]);
    bool changed = false;
    if (ImGui::BeginCombo(id, spec.choices.at(std::size_t(v)).c_str())) {
      for (int i = 0; i < int(spec.choices.size()); ++i)
        if (ImGui::Selectable(spec.choices[std::size_t(i)].c_str(), i == v)) {
          value.v[0] = i;
          changed = true;
        }
      ImGui::EndCombo();
    }
    return changed;
  }
  case ParamType::Vec3:
  case ParamType::Color: {
    float v[3] = {float(value.v[0]), float(value.v[1]), float(value.v[2])};
    const bool changed = spec.type == ParamType::Color && spec.max <= 1.0
                             ? ImGui::ColorEdit3(id, v, ImGuiColorEditFlags_Float)
                             : ImGui::DragFloat3(id, v, 0.01f, float(spec.min), float(spec.max), "%.3f", flags);
    if (changed)
      for (int c = 0; c < 3; ++c)
        value.v[std::size_t(c)] = fromWidget(double(v[c]), spec);
    return changed;
  }
  }
  return false;
}

} // namespace

bool helpMarkerHovered() {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  return ImGui::IsItemHovered();
}

void helpTooltip(const char* text) {
  ImGui::BeginTooltip();
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
  ImGui::TextUnformatted(text);
  ImGui::PopTextWrapPos();
  ImGui::EndTooltip();
}

bool labelFits(const char* label, float after) {
  const ImGuiStyle& style = ImGui::GetStyle();
  return ImGui::CalcTextSize(label).x + style.ItemSpacing.x + after <= ImGui::GetContentRegionAvail().x;
}

void wrappedLabel(const char* label) {
  ImGui::PushTextWrapPos(0.0f); // the window's right edge
  ImGui::TextUnformatted(label);
  ImGui::PopTextWrapPos();
}

bool drawParamControl(const ParamSpec& spec, ParamValue& value) {
  ImGui::PushID(spec.key.c_str());
  // The label, "(?)" and "reset" share a line when they fit; a longer label wraps (never cut at
  // the panel's edge) and the markers follow on the next line.
  const ImGuiStyle& style = ImGui::GetStyle();
  const bool isDefault = value == spec.def;
  const float markers = ImGui::CalcTextSize("(?)").x +
                        (isDefault ? 0.0f
                                   : style.ItemSpacing.x + ImGui::CalcTextSize("reset").x + 2 * style.FramePadding.x);
  if (labelFits(spec.label.c_str(), markers)) {
    ImGui::TextUnformatted(spec.label.c_str());
    if (helpMarkerHovered()) helpTooltip(tooltipText(spec).c_str());
  } else {
    wrappedLabel(spec.label.c_str());
    ImGui::TextDisabled("(?)");
    if (ImGui::IsItemHovered()) helpTooltip(tooltipText(spec).c_str());
  }
  bool changed = false;
  if (!isDefault) {
    ImGui::SameLine();
    if (ImGui::SmallButton("reset")) {
      value = spec.def;
      changed = true;
    }
  }
  ImGui::SetNextItemWidth(-1.0f);
  changed |= drawValue(spec, value, "##value");
  ImGui::PopID();
  return changed;
}

void drawParamGroup(const ParamSet& params, const std::string& prefix, std::vector<ParamEdit>& edits) {
  for (const auto& spec : params.specs()) {
    if (spec.key.rfind(prefix, 0) != 0) continue;
    ParamValue value = params.value(spec.key);
    if (drawParamControl(spec, value)) edits.push_back({spec.key, value});
  }
}

} // namespace rtlab
