// Scene section: built-in scenes and files (also dropped onto the window), presets, bookmarks
// and lecture mode, screenshots; and the lights section.
#include "ui/panels.h"

#include "scene/builtin.h"
#include "viewer/viewer_actions.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>

namespace rtlab {
namespace {

// The next item's width so that it and `buttons` (labels of the buttons after it on its line)
// fit in the panel: the buttons are never cut at the panel's edge.
void widthBeforeButtons(std::initializer_list<const char*> buttons) {
  const ImGuiStyle& style = ImGui::GetStyle();
  float width = 0.0f;
  for (const char* b : buttons)
    width += ImGui::CalcTextSize(b).x + 2 * style.FramePadding.x + style.ItemSpacing.x;
  ImGui::SetNextItemWidth(std::max(ImGui::GetContentRegionAvail().x - width, ImGui::GetFontSize() * 3));
}

} // namespace

void drawScenePanel(ViewerState& state) {
  if (ImGui::BeginCombo("scene", state.sceneSpec.c_str())) {
    for (const auto& name : builtinSceneNames())
      if (ImGui::Selectable(name.c_str(), name == state.sceneSpec))
        runGuarded(state, [&] { loadSceneAction(state, name); });
    ImGui::EndCombo();
  }
  helpMarker("A built-in scene, or type a .gltf/.glb path below, or drop a file onto the window.");
  widthBeforeButtons({"Open"});
  ImGui::InputText("##scenefile", &state.scenePathInput);
  ImGui::SameLine();
  if (ImGui::Button("Open")) runGuarded(state, [&] { loadSceneAction(state, state.scenePathInput); });

  widthBeforeButtons({"Save", "Load", "(?)"});
  ImGui::InputText("##preset", &state.presetPathInput);
  ImGui::SameLine();
  if (ImGui::Button("Save"))
    runGuarded(state, [&] {
      savePresetAction(state, state.presetPathInput);
      setStatus(state, "saved preset " + state.presetPathInput, true);
    });
  ImGui::SameLine();
  if (ImGui::Button("Load")) runGuarded(state, [&] { loadPresetAction(state, state.presetPathInput); });
  helpMarker("Presets use the --preset format: scene, techniques and every parameter.");

  widthBeforeButtons({"Screenshot", "(?)"});
  ImGui::InputText("##shot", &state.screenshotPathInput);
  ImGui::SameLine();
  if (ImGui::Button("Screenshot")) state.pendingScreenshots.push_back(state.screenshotPathInput);
  helpMarker("Writes the window, panel included, as PNG (also F12).");

  ImGui::Checkbox("Lecture mode", &state.lecture);
  helpMarker("Large text; Left/Right step through the bookmarks (--bookmarks FILE).");
  if (!state.bookmarks.empty()) {
    const std::string current =
        state.bookmark >= 0 ? state.bookmarks[std::size_t(state.bookmark)].name : std::string("(none)");
    if (ImGui::BeginCombo("bookmark", current.c_str())) {
      for (int i = 0; i < int(state.bookmarks.size()); ++i)
        if (ImGui::Selectable(state.bookmarks[std::size_t(i)].name.c_str(), i == state.bookmark))
          runGuarded(state, [&] { bookmarkAction(state, i); });
      ImGui::EndCombo();
    } else if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("%s", current.c_str()); // the name, when the combo's preview cuts it
    }
  }
  if (ImGui::Button("Reset camera (R)")) resetCameraAction(state);
  // The second button goes on the next line when both do not fit.
  const float frameButton = ImGui::CalcTextSize("Frame scene (F)").x + 2 * ImGui::GetStyle().FramePadding.x;
  if (ImGui::GetContentRegionAvail().x - ImGui::GetItemRectSize().x - ImGui::GetStyle().ItemSpacing.x >= frameButton)
    ImGui::SameLine();
  if (ImGui::Button("Frame scene (F)")) frameSceneAction(state);
}

void drawLightPanel(ViewerState& state) {
  std::vector<ParamEdit> edits;
  for (std::size_t i = 0; i < state.scene.lights.size(); ++i) {
    const std::string prefix = "light" + std::to_string(i) + ".";
    if (ImGui::TreeNodeEx(prefix.c_str(), i == 0 ? ImGuiTreeNodeFlags_DefaultOpen : 0, "light %zu", i)) {
      drawParamGroup(state.params, prefix, edits);
      ImGui::TreePop();
    }
  }
  applyEdits(state, edits);
}

} // namespace rtlab
