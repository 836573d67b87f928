// The script action "report": the viewer's state as JSON, written atomically.
// {"schema": 1, "frames", "scene", "techniques", "render_size": [w, h], "render_scale",
//  "view": {"aov", "mode", "min", "max", "false_color"}, "compare": {"mode", "divider"},
//  "reference": {"aov", "samples", "running", "rmse", "flip", "metrics_samples", "error"},
//  "timing", "frame_ms" (the last frame), "frame_ms_median" and "frame_ms_samples" (the frames of
//  the timings graph: up to 120, since the render size last changed), "passes": [{"name", "technique", "ms"}],
//  "gl_errors", "shader_errors": ["file:line: ..."], "lecture", "bookmark", "params": {KEY: value}}
// rmse and flip are null until the live metrics have been computed.
#pragma once
#include "viewer/viewer_state.h"

#include <nlohmann/json.hpp>

#include <string>

namespace rtlab {

nlohmann::ordered_json viewerReport(const ViewerState& state, int renderWidth, int renderHeight);
void writeViewerReport(const std::string& path, const ViewerState& state, int renderWidth, int renderHeight);

} // namespace rtlab
