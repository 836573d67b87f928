#include "ui/panels.h"

#include "util/error.h"
#include "viewer/viewer_actions.h"

#include <imgui.h>

namespace rtlab {

void runGuarded(ViewerState& state, const std::function<void()>& action) {
  try {
    action();
  } catch (const Error& e) {
    state.status = e.what();
  }
}

void applyEdits(ViewerState& state, const std::vector<ParamEdit>& edits) {
  for (const auto& e : edits) runGuarded(state, [&] { setParamValueAction(state, e.key, e.value); });
}

void drawViewerPanel(ViewerState& state) {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const float width = std::min(viewport->Size.x * 0.45f, ImGui::GetFontSize() * 22.0f);
  ImGui::SetNextWindowPos(viewport->Pos, ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(width, viewport->Size.y), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.85f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse;
  if (ImGui::Begin("rtlab", nullptr, flags)) {
    if (!state.status.empty()) ImGui::TextWrapped("%s", state.status.c_str());
    for (const auto& e : state.shaderErrors) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", e.c_str());
    if (ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) drawScenePanel(state);
    if (ImGui::CollapsingHeader("Techniques", ImGuiTreeNodeFlags_DefaultOpen)) drawTechniquePanel(state);
    if (ImGui::CollapsingHeader("Lights")) drawLightPanel(state);
    if (ImGui::CollapsingHeader("Tone mapping")) drawTonemapPanel(state);
    if (ImGui::CollapsingHeader("Debug view")) drawViewPanel(state);
    if (ImGui::CollapsingHeader("Compare", ImGuiTreeNodeFlags_DefaultOpen)) drawComparePanel(state);
    if (ImGui::CollapsingHeader("Timings", ImGuiTreeNodeFlags_DefaultOpen)) drawTimingsPanel(state);
  }
  ImGui::End();
}

} // namespace rtlab
