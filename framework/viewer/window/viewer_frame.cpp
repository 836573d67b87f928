#include "viewer/window/viewer_frame.h"

#include "frame/aovs.h"
#include "gl/debug.h"
#include "shading/base_passes.h"
#include "util/error.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace rtlab {

ViewerFrame::ViewerFrame(const TechniqueRegistry& registry, TimingMethod timing)
    : m_registry(registry), m_renderer(registry), m_timer(timing), m_display(m_renderer.programs()) {}

FrameOutputs ViewerFrame::outputsFor(ViewerState& state, bool reference, const std::string& referenceAov) {
  FrameOutputs outputs;
  outputs.displayColor = true;
  if (state.view.mode != DebugMode::Off) {
    // Rendered only where draw(), a snapshot or the auto range uses it: the reference and
    // difference views replace the full-screen debug view, and hide the picture-in-picture.
    const bool referenceShown =
        state.compare.mode == CompareMode::Reference || state.compare.mode == CompareMode::Difference;
    const bool used = state.view.autoRangeRequested ||
                      (state.view.mode == DebugMode::Full && (!referenceShown || state.snapshotRequested)) ||
                      (state.view.mode == DebugMode::Pip && state.compare.mode == CompareMode::Off);
    try {
      m_renderer.checkAov(state.view.aov);
      if (used) outputs.aovs.push_back(state.view.aov);
    } catch (const Error& e) {
      state.status = std::string(e.what()) + ": debug view off";
      state.view.mode = DebugMode::Off;
    }
  }
  if (reference) {
    if (std::find(outputs.aovs.begin(), outputs.aovs.end(), referenceAov) == outputs.aovs.end())
      outputs.aovs.push_back(referenceAov);
    outputs.surfaces = true;
  }
  return outputs;
}

void ViewerFrame::recordTimings(ViewerState& state) {
  state.timingMethod = timingName(m_timer.method());
  state.frameMs = m_timer.frameMs();
  state.passes.clear();
  for (const auto& s : m_timer.frameSamples())
    state.passes.push_back({s.pass, s.technique, s.ms});
  state.frameHistory.push_back(float(state.frameMs));
  while (state.frameHistory.size() > kHistory)
    state.frameHistory.pop_front();
}

void ViewerFrame::render(ViewerState& state, int windowWidth, int windowHeight, bool referenceWanted, unsigned seed) {
  if (state.sceneChanged) {
    m_renderer.setScene(state.scene);
    state.sceneChanged = false;
  }
  if (state.techniquesChanged) {
    m_renderer.setTechniques(state.selection.ordered());
    state.techniquesChanged = false;
  }
  const int width = std::max(1, int(std::lround(windowWidth * state.renderScale)));
  const int height = std::max(1, int(std::lround(windowHeight * state.renderScale)));
  if (width != m_width || height != m_height) state.frameHistory.clear(); // the graph is per render size
  m_width = width;
  m_height = height;
  bool reference =
      referenceWanted || state.compare.mode == CompareMode::Reference || state.compare.mode == CompareMode::Difference;
  const std::string referenceAov = referenceAovFor(state);
  const auto now = std::chrono::steady_clock::now();
  if (m_shaderError.empty() || now >= m_retryAt) {
    try {
      m_renderer.render(state.params, m_width, m_height, outputsFor(state, reference, referenceAov), m_timer);
      m_rendered = true;
      m_shaderError.clear();
      recordTimings(state);
      ++state.frames;
    } catch (const Error& e) {
      // A program that never compiled (its technique was switched on while its file is broken):
      // the last picture stays and the message is shown; compiling is tried again twice a second.
      if (e.code() != ExitCode::Shader) throw;
      m_shaderError = e.what();
      m_retryAt = now + std::chrono::milliseconds(500);
    }
  }
  if (!m_shaderError.empty()) reference = false;
  state.glErrors += drainGlErrors();
  if (state.view.autoRangeRequested && m_rendered) autoRange(state);
  if (reference && m_rendered)
    m_reference.update(state, m_renderer, seed, m_width, m_height);
  else
    m_reference.stop(state);
  draw(state, windowWidth, windowHeight, referenceAov);
  state.glErrors += drainGlErrors();
}

DisplaySide ViewerFrame::aovSide(const std::string& aov) {
  return DisplaySide{m_renderer.resource(aovResource(aov)), DisplayKind::Data, aovChannels(aov, m_registry)};
}

void ViewerFrame::autoRange(ViewerState& state) {
  state.view.autoRangeRequested = false;
  if (state.view.mode == DebugMode::Off) return;
  const ValueRange range = validRange(m_renderer.readAov(state.view.aov)); // background holds 0, not data
  if (!(range.min < range.max)) {
    state.status = "auto range: the view holds a single value";
    return;
  }
  state.view.min = range.min;
  state.view.max = range.max;
}

void ViewerFrame::takeSnapshot(ViewerState& state, const DisplaySide& side) {
  state.snapshotRequested = false;
  if (!side.texture) return;
  m_snapshot = copyTexture(*side.texture, "viewer.snapshot");
  m_snapshotSide = DisplaySide{&m_snapshot, side.kind, side.channels};
  state.status = "snapshot taken";
}

void ViewerFrame::draw(ViewerState& state, int windowWidth, int windowHeight, const std::string& referenceAov) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, windowWidth, windowHeight);
  glDisable(GL_SCISSOR_TEST);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  if (!m_rendered) return;
  const DebugViewSettings& v = state.view;
  DisplayRequest r;
  r.width = windowWidth;
  r.height = windowHeight;
  r.min = v.min;
  r.max = v.max;
  r.falseColor = v.falseColor;
  r.divider = state.compare.divider;
  r.a = v.mode == DebugMode::Full ? aovSide(v.aov) : DisplaySide{m_renderer.resource(res::kColorLdr)};
  if (state.snapshotRequested) takeSnapshot(state, r.a);
  switch (state.compare.mode) {
  case CompareMode::Reference:
  case CompareMode::Difference:
    r.a = aovSide(referenceAov);
    r.b = DisplaySide{m_reference.texture(), DisplayKind::Data, m_reference.texture() ? m_reference.channels() : 1};
    r.mode = state.compare.mode == CompareMode::Reference ? DisplayRequest::Wipe : DisplayRequest::Difference;
    break;
  case CompareMode::Snapshot:
    r.b = m_snapshotSide;
    r.mode = DisplayRequest::Wipe;
    break;
  case CompareMode::Off:
    break;
  }
  m_display.draw(r);
  if (v.mode == DebugMode::Pip && state.compare.mode == CompareMode::Off) {
    DisplayRequest pip = r;
    pip.a = aovSide(v.aov);
    pip.b = {};
    pip.mode = DisplayRequest::Single;
    pip.width = windowWidth / 3;
    pip.height = windowHeight / 3;
    pip.x = windowWidth - pip.width - 8;
    pip.y = 8;
    m_display.draw(pip);
  }
}

} // namespace rtlab
