// Debug-view and compare sections: any AOV or active technique's debug view, full screen or
// picture-in-picture, with a value range and false color; the render scale; the compare mode
// (reference wipe, snapshot wipe, difference heat map) with its divider and live metrics.
#include "ui/panels.h"

#include "frame/registry.h"
#include "frame/stages.h"
#include "viewer/script.h"
#include "viewer/viewer_actions.h"

#include <imgui.h>

namespace rtlab {
namespace {

std::vector<std::string> viewableAovs(const ViewerState& state) {
  std::vector<std::string> names;
  for (const auto& a : builtinAovs())
    names.push_back(a.name);
  for (const auto& id : state.selection.ordered())
    for (const auto& v : state.registry->get(id).info.debugViews)
      names.push_back(v.name);
  return names;
}

template <typename Mode> void modeRadios(Mode& mode, std::initializer_list<std::pair<const char*, Mode>> choices) {
  bool first = true;
  for (const auto& [label, value] : choices) {
    if (!first) ImGui::SameLine();
    first = false;
    if (ImGui::RadioButton(label, mode == value)) mode = value;
  }
}

} // namespace

void drawViewPanel(ViewerState& state) {
  DebugViewSettings& v = state.view;
  if (ImGui::BeginCombo("AOV", v.aov.c_str())) {
    for (const auto& name : viewableAovs(state))
      if (ImGui::Selectable(name.c_str(), name == v.aov)) v.aov = name;
    ImGui::EndCombo();
  }
  modeRadios(v.mode, {{"off", DebugMode::Off}, {"full", DebugMode::Full}, {"pip", DebugMode::Pip}});
  float range[2] = {v.min, v.max};
  if (ImGui::DragFloat2("range", range, 0.01f, -1e6f, 1e6f, "%.4g") && range[0] < range[1]) {
    v.min = range[0];
    v.max = range[1];
  }
  helpMarker("Values from min to max map to black..white, or through the false-color ramp (one-channel data).");
  if (ImGui::Button("auto range")) v.autoRangeRequested = true;
  helpMarker("Sets the range to the smallest and largest value of the shown AOV (surface pixels).");
  ImGui::SameLine();
  ImGui::Checkbox("false color", &v.falseColor);
  float scale = state.renderScale;
  if (ImGui::SliderFloat("render scale", &scale, float(kRenderScaleMin), float(kRenderScaleMax), "%.2f"))
    runGuarded(state, [&] { renderScaleAction(state, scale); });
  helpMarker("The frame is rendered at this fraction of the window's size: lower keeps a software rasterizer "
             "interactive.");
}

void drawComparePanel(ViewerState& state) {
  CompareSettings& c = state.compare;
  modeRadios(c.mode, {{"off", CompareMode::Off}, {"reference", CompareMode::Reference}});
  modeRadios(c.mode, {{"snapshot", CompareMode::Snapshot}, {"difference", CompareMode::Difference}});
  ImGui::SliderFloat("divider", &c.divider, 0.0f, 1.0f, "%.2f");
  helpMarker("Drag the divider here, or Ctrl + left drag on the picture.");
  if (ImGui::Button("Take snapshot")) state.snapshotRequested = true;
  helpMarker("Freezes the current picture as the right side of the snapshot wipe.");
  const auto& r = state.reference;
  if (!r.aov.empty()) {
    if (r.exact && r.running)
      ImGui::TextWrapped("reference: %s, exact, computing... (the UI does not wait for it)", r.aov.c_str());
    else if (r.exact)
      ImGui::TextWrapped("reference: %s, exact, computed in %.2f s", r.aov.c_str(), r.seconds);
    else
      ImGui::TextWrapped("reference: %s, %d spp%s", r.aov.c_str(), r.samples, r.running ? " (refining)" : "");
    if (r.rmse && r.exact)
      ImGui::TextWrapped("RMSE %.4f  FLIP %.4f  against the exact reference", *r.rmse, r.flip.value_or(0.0));
    else if (r.rmse)
      ImGui::TextWrapped("RMSE %.4f  FLIP %.4f  at %d spp", *r.rmse, r.flip.value_or(0.0), r.metricsSamples);
    else if (r.exact && r.waiting.empty())
      ImGui::TextDisabled("metrics once the reference is computed");
    else
      ImGui::TextDisabled("%s",
                          r.waiting.empty() ? "metrics once the reference has converged enough" : r.waiting.c_str());
  }
  if (!r.error.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", r.error.c_str());
}

} // namespace rtlab
