#include "viewer/window/viewer_frame.h"

#include "frame/aovs.h"
#include "gl/debug.h"
#include "gl/state.h"
#include "shading/base_passes.h"
#include "util/error.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace rtlab {
namespace {

constexpr int kPipTopMarginPx = 80; // room for the info overlay's lines at the region's top

} // namespace

ViewerFrame::ViewerFrame(const TechniqueRegistry& registry, TimingMethod timing)
    : m_registry(registry), m_renderer(registry), m_timer(timing), m_display(m_renderer.programs()),
      m_exposure(m_renderer.programs()) {}

FrameOutputs ViewerFrame::outputsFor(ViewerState& state, bool reference, const std::string& referenceAov,
                                     bool measureExposure) {
  FrameOutputs outputs;
  outputs.displayColor = true;
  if (measureExposure) outputs.colors.push_back("hdr"); // the linear colour the exposure applies to
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
      setStatus(state, std::string(e.what()) + ": debug view off", false);
      state.view.mode = DebugMode::Off;
    }
  }
  if (reference) {
    if (std::find(outputs.aovs.begin(), outputs.aovs.end(), referenceAov) == outputs.aovs.end())
      outputs.aovs.push_back(referenceAov);
    addReferenceInputs(referenceAov, outputs);
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
  const PixelRect& region = state.layout.frame;
  const int width = std::max(1, int(std::lround(region.width * state.renderScale)));
  const int height = std::max(1, int(std::lround(region.height * state.renderScale)));
  if (width != m_width || height != m_height) state.frameHistory.clear(); // the graph is per render size
  m_width = width;
  m_height = height;
  bool reference =
      referenceWanted || state.compare.mode == CompareMode::Reference || state.compare.mode == CompareMode::Difference;
  const std::string referenceAov = referenceAovFor(state);
  const auto now = std::chrono::steady_clock::now();
  if (const auto readout = m_exposure.poll()) state.exposure = *readout;
  if (m_shaderError.empty() || now >= m_retryAt) {
    try {
      gl::restoreKnownState(); // the display and UI drawing leave their own state (docs/frame-graph.md)
      const bool measure = m_exposure.due(now);
      m_renderer.render(state.params, m_width, m_height, outputsFor(state, reference, referenceAov, measure), m_timer);
      m_rendered = true;
      m_shaderError.clear();
      recordTimings(state);
      ++state.frames;
      // Untimed, after the frame's passes: the reduction is read back at a later frame.
      if (measure)
        if (const gl::Texture* hdr = m_renderer.resource(m_renderer.colorVersionResource("hdr"))) m_exposure.start(*hdr, now);
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
    setStatus(state, "auto range: the view holds a single value", false);
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
  setStatus(state, "snapshot taken", true);
}

void ViewerFrame::draw(ViewerState& state, int windowWidth, int windowHeight, const std::string& referenceAov) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, windowWidth, windowHeight);
  glDisable(GL_SCISSOR_TEST);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  state.colorBar.shown = false;
  state.wipeLeft.clear();
  state.wipeRight.clear();
  if (!m_rendered) return;
  const DebugViewSettings& v = state.view;
  const PixelRect& region = state.layout.frame;
  DisplayRequest r;
  r.x = region.x;
  r.y = windowHeight - region.y - region.height; // GL's origin is the lower left
  r.width = region.width;
  r.height = region.height;
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
    if (r.mode == DisplayRequest::Wipe) { // the AOV's name is on the colour bar
      std::string techniques;
      for (const auto& id : state.selection.ordered())
        techniques += (techniques.empty() ? "" : ", ") + id;
      state.wipeLeft = techniques.empty() ? std::string("no technique") : techniques;
      state.wipeRight = "reference";
    }
    break;
  case CompareMode::Snapshot:
    r.b = m_snapshotSide;
    r.mode = DisplayRequest::Wipe;
    if (r.b.texture) {
      state.wipeLeft = "live";
      state.wipeRight = "snapshot";
    }
    break;
  case CompareMode::Off:
    break;
  }
  m_display.draw(r);
  DisplayRequest shown = r; // the picture whose values the colour bar explains
  if (v.mode == DebugMode::Pip && state.compare.mode == CompareMode::Off) {
    DisplayRequest pip = r;
    pip.a = aovSide(v.aov);
    pip.b = {};
    pip.mode = DisplayRequest::Single;
    pip.width = region.width / 3;
    pip.height = region.height / 3;
    // Top right, below the info overlay; the colour bar and the caption keep the bottom.
    pip.x = region.x + region.width - pip.width - 8;
    pip.y = std::max(r.y + r.height - pip.height - kPipTopMarginPx, r.y);
    m_display.draw(pip);
    shown = pip;
  }
  drawColorBar(state, shown, windowHeight);
}

void ViewerFrame::drawColorBar(ViewerState& state, const DisplayRequest& shown, int windowHeight) {
  const bool difference = shown.mode == DisplayRequest::Difference && shown.b.texture;
  const bool data = shown.a.kind == DisplayKind::Data || (shown.b.texture && shown.b.kind == DisplayKind::Data);
  if (!difference && !data) return;
  auto& bar = state.colorBar;
  bar.shown = true;
  // The difference heat map is always false color, from 0 to the range's width (display.frag).
  bar.falseColor = difference || (shown.falseColor && shown.a.channels == 1);
  bar.min = difference ? 0.0f : shown.min;
  bar.max = difference ? shown.max - shown.min : shown.max;
  bar.label = difference ? "|frame - reference|"
                         : state.compare.mode == CompareMode::Reference ? referenceAovFor(state) : state.view.aov;
  const PixelRect& rect = state.layout.colorBar;
  DisplayRequest ramp;
  ramp.a = shown.a; // bound but not sampled: the ramp mode reads only the coordinates
  ramp.mode = DisplayRequest::Ramp;
  ramp.falseColor = bar.falseColor;
  ramp.x = rect.x;
  ramp.y = windowHeight - rect.y - rect.height;
  ramp.width = rect.width;
  ramp.height = rect.height;
  m_display.draw(ramp);
}

} // namespace rtlab
