#include "viewer/window/report.h"

#include "util/atomic_file.h"
#include "viewer/viewer_actions.h"

#include <algorithm>

namespace rtlab {
namespace {

nlohmann::ordered_json optionalNumberJson(const std::optional<double>& v) {
  return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(nullptr);
}

} // namespace

nlohmann::ordered_json viewerReport(const ViewerState& state, int renderWidth, int renderHeight) {
  nlohmann::ordered_json j;
  j["schema"] = 1;
  j["frames"] = state.frames;
  j["scene"] = state.sceneSpec;
  j["techniques"] = state.selection.ordered();
  j["render_size"] = {renderWidth, renderHeight};
  j["render_scale"] = state.renderScale;
  j["view"] = {{"aov", state.view.aov},
               {"mode", debugModeName(state.view.mode)},
               {"min", state.view.min},
               {"max", state.view.max},
               {"false_color", state.view.falseColor}};
  j["compare"] = {{"mode", compareModeName(state.compare.mode)}, {"divider", state.compare.divider}};
  const auto& r = state.reference;
  j["reference"] = {{"aov", r.aov},
                    {"samples", r.samples},
                    {"running", r.running},
                    {"exact", r.exact},
                    {"seconds", r.seconds},
                    {"rmse", optionalNumberJson(r.rmse)},
                    {"flip", optionalNumberJson(r.flip)},
                    {"metrics_samples", r.metricsSamples},
                    {"error", r.error}};
  j["timing"] = state.timingMethod;
  j["frame_ms"] = state.frameMs;
  std::vector<float> history(state.frameHistory.begin(), state.frameHistory.end());
  std::sort(history.begin(), history.end());
  j["frame_ms_median"] =
      history.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(history[history.size() / 2]);
  j["frame_ms_samples"] = history.size();
  auto passes = nlohmann::ordered_json::array();
  for (const auto& p : state.passes)
    passes.push_back({{"name", p.pass}, {"technique", p.technique}, {"ms", p.ms}});
  j["passes"] = passes;
  j["gl_errors"] = state.glErrors;
  j["shader_errors"] = state.shaderErrors;
  j["lecture"] = state.lecture;
  j["bookmark"] = state.bookmark;
  auto rect = [](const PixelRect& r) { return nlohmann::ordered_json::array({r.x, r.y, r.width, r.height}); };
  j["layout"] = {{"panel_shown", state.showPanel},
                 {"panel", rect(state.layout.panel)},
                 {"frame", rect(state.layout.frame)},
                 {"open_sections", state.openSections},
                 {"color_bar", state.colorBar.shown ? rect(state.layout.colorBar) : nlohmann::ordered_json(nullptr)}};
  if (state.colorBar.shown)
    j["color_bar"] = {{"label", state.colorBar.label},
                      {"min", state.colorBar.min},
                      {"max", state.colorBar.max},
                      {"false_color", state.colorBar.falseColor}};
  else
    j["color_bar"] = nullptr;
  j["recorded_frames"] = state.recordedFrames;
  j["params"] = state.params.toJson();
  return j;
}

void writeViewerReport(const std::string& path, const ViewerState& state, int renderWidth, int renderHeight) {
  writeTextAtomically(path, viewerReport(state, renderWidth, renderHeight).dump(2) + "\n");
}

} // namespace rtlab
