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
  for (const auto& e : edits)
    runGuarded(state, [&] { setParamValueAction(state, e.key, e.value); });
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
    for (const auto& e : state.shaderErrors)
      ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", e.c_str());
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

void drawInfoOverlay(const ViewerState& state, int renderWidth, int renderHeight) {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + viewport->Size.x - 8.0f, viewport->Pos.y + 8.0f), ImGuiCond_Always,
                          ImVec2(1.0f, 0.0f));
  ImGui::SetNextWindowBgAlpha(0.6f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoSavedSettings;
  if (ImGui::Begin("##info", nullptr, flags)) {
    ImGui::Text("%.1f ms (%s)  %dx%d", state.frameMs, state.timingMethod.c_str(), renderWidth, renderHeight);
    const auto& r = state.reference;
    if (state.compare.mode == CompareMode::Reference || state.compare.mode == CompareMode::Difference) {
      if (r.rmse)
        ImGui::Text("%s vs reference: RMSE %.4f  FLIP %.4f  (%d spp)", r.aov.c_str(), *r.rmse, r.flip.value_or(0.0),
                    r.metricsSamples);
      else
        ImGui::Text("reference: %d spp", r.samples);
    }
  }
  ImGui::End();
}

void drawLectureCaption(const ViewerState& state) {
  if (!state.lecture || state.bookmark < 0) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + viewport->Size.x - 8.0f, viewport->Pos.y + viewport->Size.y - 8.0f),
                          ImGuiCond_Always, ImVec2(1.0f, 1.0f));
  ImGui::SetNextWindowBgAlpha(0.6f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoSavedSettings;
  if (ImGui::Begin("##lecture", nullptr, flags))
    ImGui::Text("%d/%zu  %s", state.bookmark + 1, state.bookmarks.size(),
                state.bookmarks[std::size_t(state.bookmark)].name.c_str());
  ImGui::End();
}

} // namespace rtlab
