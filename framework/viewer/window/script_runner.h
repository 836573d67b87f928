// Runs a validated `--script` (viewer/script.h) inside the viewer's loop: step() is called once
// per frame before rendering and runs actions until one has to wait ("wait" for frames,
// "wait_samples" for the progressive reference, "ramp" for its frames); the window's own actions (screenshot,
// snapshot, report) are queued on the state and happen after the frame they follow.
#pragma once
#include "viewer/script.h"
#include "viewer/viewer_state.h"

#include <chrono>
#include <functional>
#include <optional>
#include <vector>

namespace rtlab {

class ScriptRunner {
public:
  // `report` writes the report file (report.h); it is called once the current frame is drawn.
  ScriptRunner(std::vector<ScriptAction> actions, std::function<void(const std::string&)> report)
      : m_actions(std::move(actions)), m_report(std::move(report)) {}

  // Runs actions until one waits or the script ends. Errors of an action propagate (the viewer
  // exits with their code; validation before the first frame makes them rare).
  void step(ViewerState& state);
  bool finished() const {
    return m_next >= m_actions.size() && m_waitFrames == 0 && !m_waitingSamples && !m_ramp;
  }
  // True while a "wait_samples" waits: the reference must run even with compare off.
  bool wantsReference() const { return m_waitingSamples; }
  // Reports to write after this frame's picture (the caller calls flushReports then).
  void flushReports();

private:
  bool run(const ScriptAction& action, ViewerState& state); // false: wait before the next action
  bool rampStep(ViewerState& state);                        // false: the ramp goes on next frame
  struct Ramp {
    std::string key;
    double from = 0, to = 0;
    long frames = 1, step = 0;
  };
  std::optional<Ramp> m_ramp;
  std::vector<ScriptAction> m_actions;
  std::function<void(const std::string&)> m_report;
  std::vector<std::string> m_pendingReports;
  std::size_t m_next = 0;
  long m_waitFrames = 0;
  bool m_waitingSamples = false;
  int m_samples = 0;
  std::chrono::steady_clock::time_point m_deadline;
};

} // namespace rtlab
