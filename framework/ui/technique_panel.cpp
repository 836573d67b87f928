// Techniques section: for every stage of the frame, a selector of its registered techniques with
// an "off" choice (checkboxes for a stack stage), the stage's own parameters and the active
// technique's parameters; and the tone-mapping section. All of it comes from the stage table, the
// registry and the ParamSpecs: a new technique appears here without a line of UI code.
#include "ui/panels.h"

#include "frame/registry.h"
#include "frame/stages.h"
#include "viewer/viewer_actions.h"

#include <imgui.h>

namespace rtlab {
namespace {

void drawExclusiveSelector(ViewerState& state, const StageInfo& stage) {
  const TechniqueRegistry& registry = *state.registry;
  const std::string active = state.selection.activeIn(stage.id);
  if (ImGui::BeginCombo(stage.id.c_str(), active.empty() ? "off" : active.c_str())) {
    if (ImGui::Selectable("off", active.empty()))
      runGuarded(state, [&] { selectTechniqueAction(state, stage.id, "off"); });
    for (const auto& e : registry.entries()) {
      if (e.info.stage != stage.id) continue;
      if (ImGui::Selectable(e.info.id.c_str(), e.info.id == active))
        runGuarded(state, [&] { selectTechniqueAction(state, stage.id, e.info.id); });
      if (ImGui::IsItemHovered() && !e.info.summary.empty()) ImGui::SetTooltip("%s", e.info.summary.c_str());
    }
    ImGui::EndCombo();
  }
}

void drawStackSelector(ViewerState& state, const StageInfo& stage) {
  for (const auto& e : state.registry->entries()) {
    if (e.info.stage != stage.id) continue;
    bool on = state.selection.isActive(e.info.id);
    if (ImGui::Checkbox(e.info.id.c_str(), &on))
      runGuarded(state, [&] { setTechniqueActiveAction(state, e.info.id, on); });
  }
}

} // namespace

void drawTechniquePanel(ViewerState& state) {
  const TechniqueRegistry& registry = *state.registry;
  std::vector<ParamEdit> edits;
  for (const auto& stage : stages()) {
    bool any = false;
    for (const auto& e : registry.entries())
      any |= e.info.stage == stage.id;
    if (!any && stage.params.empty()) continue; // a stage with nothing to choose or set
    ImGui::PushID(stage.id.c_str());
    if (stage.exclusive)
      drawExclusiveSelector(state, stage);
    else
      drawStackSelector(state, stage);
    if (!stage.params.empty() && ImGui::TreeNode("stage", "%s parameters", stage.id.c_str())) {
      drawParamGroup(state.params, stage.id + ".", edits);
      ImGui::TreePop();
    }
    for (const auto& id : state.selection.ordered()) {
      const TechniqueEntry& e = registry.get(id);
      if (e.info.stage != stage.id || e.info.params.empty()) continue;
      // The node is named by the id (short, never cut); the title follows wrapped.
      if (ImGui::TreeNodeEx(id.c_str(), ImGuiTreeNodeFlags_DefaultOpen, "%s", id.c_str())) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
        wrappedLabel(e.info.title.c_str());
        ImGui::PopStyleColor();
        drawParamGroup(state.params, id + ".", edits);
        ImGui::TreePop();
      }
    }
    ImGui::PopID();
  }
  applyEdits(state, edits);
}

void drawTonemapPanel(ViewerState& state) {
  std::vector<ParamEdit> edits;
  drawParamGroup(state.params, "tonemap.", edits);
  applyEdits(state, edits);
  // Read-only: the frame's log-average and largest luminance before exposure, and the exposure
  // that maps the log-average to middle grey (docs/viewer.md "Exposure readout").
  if (state.exposure)
    ImGui::TextWrapped("log-average L %.3g  max %.3g  key exposure %.3g", state.exposure->logAverageLuminance,
                       state.exposure->maxLuminance, state.exposure->keyExposure);
}

} // namespace rtlab
