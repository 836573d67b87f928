// Timings section: the frame total and each pass's ms by the foundation's timing mechanism
// (cpu-finish on software rasterizers, timer queries on a GPU; the method is shown), with a short
// history graph of frame totals.
#include "ui/panels.h"

#include <imgui.h>

#include <algorithm>
#include <deque>

namespace rtlab {

void drawTimingsPanel(ViewerState& state) {
  ImGui::TextWrapped("frame %.2f ms (%s)", state.frameMs, state.timingMethod.c_str());
  if (!state.frameHistory.empty()) {
    // Read from the deque in place: no copy of the history every frame.
    const auto& history = state.frameHistory;
    const float top = *std::max_element(history.begin(), history.end());
    const auto at = [](void* data, int i) { return (*static_cast<const std::deque<float>*>(data))[std::size_t(i)]; };
    ImGui::PlotLines("##history", at, const_cast<std::deque<float>*>(&history), int(history.size()), 0, nullptr, 0.0f,
                     top * 1.1f, ImVec2(-1.0f, ImGui::GetFontSize() * 3.0f));
  }
  if (ImGui::BeginTable("passes", 2, ImGuiTableFlags_SizingStretchProp)) {
    for (const auto& p : state.passes) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      if (p.technique.empty())
        ImGui::TextUnformatted(p.pass.c_str());
      else
        ImGui::Text("%s [%s]", p.pass.c_str(), p.technique.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%.2f", p.ms);
    }
    ImGui::EndTable();
  }
  ImGui::Text("GL errors: %ld", state.glErrors);
}

} // namespace rtlab
