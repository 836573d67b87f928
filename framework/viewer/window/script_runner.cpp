#include "viewer/window/script_runner.h"

#include "util/log.h"
#include "viewer/json_fields.h"
#include "viewer/viewer_actions.h"

#include <cmath>

namespace rtlab {

void ScriptRunner::step(ViewerState& state) {
  if (m_waitFrames > 0) {
    if (--m_waitFrames > 0) return;
  }
  if (m_waitingSamples) {
    // An exact reference has no samples to wait for: computed and measured against is reached.
    const auto& r = state.reference;
    const bool reached = r.exact ? r.samples > 0 && r.metricsSamples >= r.samples
                                 : r.samples >= m_samples && r.metricsSamples >= m_samples;
    if (!reached && std::chrono::steady_clock::now() < m_deadline) return;
    if (!reached)
      logWarn("script: wait_samples timed out at " + std::to_string(r.samples) + " of " +
              std::to_string(m_samples) + " spp; continuing");
    m_waitingSamples = false;
  }
  if (m_ramp && !rampStep(state)) return;
  while (m_next < m_actions.size()) {
    const ScriptAction& a = m_actions[m_next++];
    logDebug("script: " + a.where());
    if (!run(a, state)) return;
  }
}

void ScriptRunner::flushReports() {
  for (const auto& file : m_pendingReports)
    m_report(file);
  m_pendingReports.clear();
}

bool ScriptRunner::rampStep(ViewerState& state) {
  Ramp& r = *m_ramp;
  ++r.step;
  const double value = rampValue(r.from, r.to, r.step, r.frames);
  if (state.params.spec(r.key).type == ParamType::Int)
    setParamAction(state, r.key, static_cast<long long>(std::llround(value)));
  else
    setParamAction(state, r.key, value);
  if (r.step < r.frames) return false;
  m_ramp.reset();
  return true;
}

bool ScriptRunner::run(const ScriptAction& a, ViewerState& state) {
  const auto& j = a.args;
  const std::string& w = a.where();
  if (a.action == "technique")
    selectTechniqueAction(state, j.at("stage"), j.at("id"));
  else if (a.action == "set")
    setParamAction(state, j.at("key"), j.at("value"));
  else if (a.action == "reset")
    resetParamAction(state, j.at("key"));
  else if (a.action == "camera") {
    auto fov = optionalNumber(j, "fov", w);
    cameraAction(state, optionalVec3(j, "position", w), optionalVec3(j, "target", w),
                 fov ? std::optional<float>(float(*fov)) : std::nullopt);
  } else if (a.action == "orbit") {
    state.camera.orbit(glm::radians(float(optionalNumber(j, "yaw", w).value_or(0.0))),
                       glm::radians(float(optionalNumber(j, "pitch", w).value_or(0.0))));
    syncCameraToParams(state);
  } else if (a.action == "view")
    viewAction(state, j);
  else if (a.action == "compare")
    compareAction(state, j);
  else if (a.action == "snapshot")
    state.snapshotRequested = true;
  else if (a.action == "wait") {
    m_waitFrames = long(j.at("frames").get<long long>());
    return m_waitFrames == 0;
  } else if (a.action == "wait_samples") {
    m_samples = int(j.at("samples").get<long long>());
    const double timeout = optionalNumber(j, "timeout_s", w).value_or(kScriptSampleTimeoutDefault);
    m_deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(long(timeout * 1000.0));
    m_waitingSamples = true;
    return false;
  } else if (a.action == "screenshot") {
    state.pendingScreenshots.push_back(j.at("file"));
    return false; // the picture of the state so far: render it before going on
  } else if (a.action == "save_preset")
    savePresetAction(state, j.at("file"));
  else if (a.action == "load_preset")
    loadPresetAction(state, j.at("file"));
  else if (a.action == "report") {
    m_pendingReports.push_back(j.at("file"));
    return false;
  } else if (a.action == "render_scale")
    renderScaleAction(state, j.at("value").get<double>());
  else if (a.action == "lecture")
    state.lecture = j.at("on").get<bool>();
  else if (a.action == "bookmark")
    bookmarkAction(state, int(j.at("index").get<long long>()));
  else if (a.action == "panel")
    panelAction(state, j.at("on").get<bool>());
  else if (a.action == "section")
    sectionAction(state, j.at("name"), optionalBool(j, "open", w).value_or(true));
  else if (a.action == "ramp") {
    m_ramp = Ramp{j.at("key"), j.at("from").get<double>(), j.at("to").get<double>(),
                  long(j.at("frames").get<long long>()), 0};
    return rampStep(state); // the first step shows in this frame
  } else if (a.action == "record") {
    state.recordDir = j.at("dir");
    state.recordedFrames = 0;
  } else if (a.action == "stop")
    state.recordDir.clear();
  else if (a.action == "quit") {
    state.quit = true;
    return false;
  }
  return true;
}

} // namespace rtlab
