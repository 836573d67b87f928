#include "ui/panels.h"

#include "util/error.h"
#include "viewer/viewer_actions.h"

#include <imgui.h>

#include <algorithm>

namespace rtlab {
namespace {

// Framebuffer pixels (the layout's unit) to ImGui's window coordinates.
float toUi(int px) {
  return float(px) / std::max(ImGui::GetIO().DisplayFramebufferScale.x, 1e-3f);
}

// A collapsing header that a script's "section" action or a bookmark's "sections" may open or
// close (ViewerState::sectionRequests, applied once).
bool section(ViewerState& state, const char* name, ImGuiTreeNodeFlags flags = 0) {
  for (const auto& [requested, open] : state.sectionRequests)
    if (requested == name) ImGui::SetNextItemOpen(open, ImGuiCond_Always);
  const bool expanded = ImGui::CollapsingHeader(name, flags);
  if (expanded) state.openSections.push_back(name);
  return expanded;
}

// Text on the picture (not a window: the panel always stays above it), on a dark box.
void labelAt(ImVec2 pos, const std::string& text, float alignX) {
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  const float pad = 4.0f;
  pos.x -= alignX * size.x;
  draw->AddRectFilled(ImVec2(pos.x - pad, pos.y - pad), ImVec2(pos.x + size.x + pad, pos.y + size.y + pad),
                      IM_COL32(0, 0, 0, 170), 3.0f);
  draw->AddText(pos, IM_COL32(255, 255, 255, 255), text.c_str());
}

std::string number(float v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", double(v));
  return text;
}

// Each half's name beside the divider, kept inside the frame's region (a label that does not fit
// beside the divider slides inwards rather than being cut at the window's edge).
void drawWipeLabels(const ViewerState& state) {
  if (state.wipeLeft.empty()) return;
  const PixelRect& f = state.layout.frame;
  const float left = toUi(f.x), right = toUi(f.x + f.width), pad = 6.0f;
  const float x = left + toUi(f.width) * state.compare.divider;
  const float y = toUi(f.y + f.height) - ImGui::GetFontSize() * 3.0f;
  const float gap = ImGui::GetFontSize() * 0.6f;
  const float wl = ImGui::CalcTextSize(state.wipeLeft.c_str()).x, wr = ImGui::CalcTextSize(state.wipeRight.c_str()).x;
  labelAt(ImVec2(std::max(x - gap, left + pad + wl), y), state.wipeLeft, 1.0f);
  labelAt(ImVec2(std::min(x + gap, right - pad - wr), y), state.wipeRight, 0.0f);
}

// The bar's minimum left of it, maximum right of it, and what it shows above it.
void drawColorBarLabels(const ViewerState& state) {
  if (!state.colorBar.shown) return;
  const PixelRect& r = state.layout.colorBar;
  const float font = ImGui::GetFontSize(), gap = font * 0.5f;
  const float middle = toUi(r.y) + toUi(r.height) * 0.5f - font * 0.5f;
  labelAt(ImVec2(toUi(r.x) - gap, middle), number(state.colorBar.min), 1.0f);
  labelAt(ImVec2(toUi(r.x + r.width) + gap, middle), number(state.colorBar.max), 0.0f);
  labelAt(ImVec2(toUi(r.x) + toUi(r.width) * 0.5f, toUi(r.y) - font * 1.4f), state.colorBar.label, 0.5f);
}

// A text box in a corner of the frame's region `f` (top right: pivotY 0, bottom right: pivotY 1),
// its text wrapped to the region's width; returns Begin()'s result (End() is the caller's).
bool beginFrameCorner(const PixelRect& f, const char* id, float pivotY) {
  const float margin = 8.0f;
  const float y = pivotY == 0.0f ? toUi(f.y) + margin : toUi(f.y + f.height) - margin;
  ImGui::SetNextWindowPos(ImVec2(toUi(f.x + f.width) - margin, y), ImGuiCond_Always, ImVec2(1.0f, pivotY));
  ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(std::max(toUi(f.width) - 2 * margin, 1.0f), FLT_MAX));
  ImGui::SetNextWindowBgAlpha(0.6f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoFocusOnAppearing;
  const bool open = ImGui::Begin(id, nullptr, flags);
  if (open) ImGui::PushTextWrapPos(std::max(toUi(f.width) - 4 * margin, 1.0f));
  return open;
}

void endFrameCorner(bool open) {
  if (open) ImGui::PopTextWrapPos();
  ImGui::End();
}

// The info overlay at the frame's top right: frame time, render size, live metrics.
void drawInfoOverlay(const ViewerState& state, int renderWidth, int renderHeight) {
  const bool open = beginFrameCorner(state.layout.frame, "##info", 0.0f);
  if (open) {
    ImGui::Text("%.1f ms (%s)  %dx%d", state.frameMs, state.timingMethod.c_str(), renderWidth, renderHeight);
    const auto& r = state.reference;
    if (state.compare.mode == CompareMode::Reference || state.compare.mode == CompareMode::Difference) {
      // An exact reference has no sample count: it is computing, or complete.
      const std::string samples = r.exact ? std::string("exact") : std::to_string(r.metricsSamples) + " spp";
      if (r.rmse)
        ImGui::TextWrapped("%s vs reference: RMSE %.4f  FLIP %.4f  (%s)", r.aov.c_str(), *r.rmse,
                           r.flip.value_or(0.0), samples.c_str());
      else if (r.exact)
        ImGui::Text("reference: %s", r.running ? ("computing " + r.aov + " (exact)...").c_str() : "exact");
      else
        ImGui::Text("reference: %d spp", r.samples);
    }
  }
  endFrameCorner(open);
}

// Lecture mode's caption: the bookmark's name at the frame's bottom right.
void drawLectureCaption(const ViewerState& state) {
  if (!state.lecture || state.bookmark < 0) return;
  const bool open = beginFrameCorner(state.layout.frame, "##lecture", 1.0f);
  if (open)
    ImGui::TextWrapped("%d/%zu  %s", state.bookmark + 1, state.bookmarks.size(),
                       state.bookmarks[std::size_t(state.bookmark)].name.c_str());
  endFrameCorner(open);
}

void drawSpeakerNotes(ViewerState& state) {
  if (!state.lecture || state.bookmark < 0) return;
  const std::string& notes = state.bookmarks[std::size_t(state.bookmark)].notes;
  if (notes.empty()) return;
  if (section(state, "Speaker notes", ImGuiTreeNodeFlags_DefaultOpen)) ImGui::TextWrapped("%s", notes.c_str());
}

// While the panel is hidden: a small button at the window's top left, shown when the mouse is near.
void drawShowPanelButton(ViewerState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  if (!(io.MousePos.x >= 0 && io.MousePos.x < ImGui::GetFontSize() * 4 && io.MousePos.y >= 0 &&
        io.MousePos.y < ImGui::GetFontSize() * 4))
    return;
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->Pos, ImGuiCond_Always);
  const ImGuiWindowFlags flags =
      ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings;
  if (ImGui::Begin("##showpanel", nullptr, flags) && ImGui::Button("Panel (Tab)")) panelAction(state, true);
  ImGui::End();
}

} // namespace

void runGuarded(ViewerState& state, const std::function<void()>& action) {
  try {
    action();
  } catch (const Error& e) {
    setStatus(state, e.what(), false);
  }
}

void applyEdits(ViewerState& state, const std::vector<ParamEdit>& edits) {
  for (const auto& e : edits)
    runGuarded(state, [&] { setParamValueAction(state, e.key, e.value); });
}

void drawViewerPanel(ViewerState& state, bool showTransient, int windowWidth) {
  state.openSections.clear();
  if (!state.showPanel) {
    drawShowPanelButton(state);
    state.sectionRequests.clear(); // applied when the panel is drawn; a hidden panel drops them
    return;
  }
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const float height = viewport->Size.y, font = ImGui::GetFontSize();
  const float scale = std::max(ImGui::GetIO().DisplayFramebufferScale.x, 1e-3f);
  const float width = toUi(state.layout.panel.width);
  ImGui::SetNextWindowPos(viewport->Pos, ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_Always);
  // Dragging the right edge resizes the panel within the layout's limits (viewer_layout.h).
  ImGui::SetNextWindowSizeConstraints(ImVec2(std::min(kPanelWidthEmMin * font, width), height),
                                      ImVec2(std::max(toUi(windowWidth) * kPanelMaxFraction, width), height));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoSavedSettings;
  if (ImGui::Begin("rtlab", nullptr, flags)) {
    // Widgets leave 6.5 font sizes for their labels ("bookmark", "scene (?)"), at every width.
    ImGui::PushItemWidth(-font * 6.5f);
    const float dragged = ImGui::GetWindowWidth();
    if (std::abs(dragged - width) > 0.5f) state.panelWidthEm = panelWidthEmFor(dragged * scale, windowWidth, font * scale);
    if (ImGui::SmallButton("Hide panel (Tab)")) panelAction(state, false);
    if (!state.status.empty() && (showTransient || !state.statusTransient))
      ImGui::TextWrapped("%s", state.status.c_str());
    for (const auto& e : state.shaderErrors)
      ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", e.c_str());
    drawSpeakerNotes(state);
    if (section(state, "Scene", ImGuiTreeNodeFlags_DefaultOpen)) drawScenePanel(state);
    if (section(state, "Techniques", ImGuiTreeNodeFlags_DefaultOpen)) drawTechniquePanel(state);
    if (section(state, "Lights")) drawLightPanel(state);
    if (section(state, "Tone mapping")) drawTonemapPanel(state);
    if (section(state, "Debug view")) drawViewPanel(state);
    if (section(state, "Compare", ImGuiTreeNodeFlags_DefaultOpen)) drawComparePanel(state);
    if (section(state, "Timings", ImGuiTreeNodeFlags_DefaultOpen)) drawTimingsPanel(state);
    ImGui::PopItemWidth();
  }
  ImGui::End();
  state.sectionRequests.clear();
}

void drawFrameOverlays(const ViewerState& state, int renderWidth, int renderHeight) {
  drawInfoOverlay(state, renderWidth, renderHeight);
  drawWipeLabels(state);
  drawColorBarLabels(state);
  drawLectureCaption(state);
}

} // namespace rtlab
