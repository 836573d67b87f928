// One frame of the viewer: brings the renderer up to date with the state (scene, techniques),
// renders at the window's size times the render scale, records timings and GL errors, keeps the
// compare mode's reference and snapshot, and draws the picture (frame_display.h) into the window.
#pragma once
#include "frame/pass_timer.h"
#include "render/renderer.h"
#include "viewer/viewer_state.h"

#include "viewer/window/exposure_meter.h"
#include "viewer/window/frame_display.h"
#include "viewer/window/reference_view.h"
#include <chrono>
#include <string>

namespace rtlab {

class ViewerFrame {
public:
  static constexpr std::size_t kHistory = 120; // frames in the timings graph

  ViewerFrame(const TechniqueRegistry& registry, TimingMethod timing);
  // Renders at the size of state.layout.frame times the render scale and draws the picture into
  // that region of the window (the rest is cleared). `referenceWanted`: keep the progressive
  // reference running even when compare mode is off (a script waiting for samples).
  void render(ViewerState& state, int windowWidth, int windowHeight, bool referenceWanted, unsigned seed);
  // The message of a program that failed to compile on first use (empty when the last frame
  // rendered); programs that compiled once are hot-reloaded instead (hot_reload.h).
  const std::string& shaderError() const { return m_shaderError; }
  int renderWidth() const { return m_width; }
  int renderHeight() const { return m_height; }
  gl::ProgramCache& programs() { return m_renderer.programs(); }

private:
  FrameOutputs outputsFor(ViewerState& state, bool reference, const std::string& referenceAov, bool measureExposure);
  void recordTimings(ViewerState& state);
  void takeSnapshot(ViewerState& state, const DisplaySide& side);
  void autoRange(ViewerState& state);
  void draw(ViewerState& state, int windowWidth, int windowHeight, const std::string& referenceAov);
  void drawColorBar(ViewerState& state, const DisplayRequest& shown, int windowHeight);
  DisplaySide aovSide(const std::string& aov);

  const TechniqueRegistry& m_registry;
  Renderer m_renderer;
  PassTimer m_timer;
  FrameDisplay m_display;
  ExposureMeter m_exposure;
  ReferenceView m_reference;
  gl::Texture m_snapshot;
  DisplaySide m_snapshotSide;
  bool m_rendered = false; // a frame has been rendered (the pool holds its textures)
  int m_width = 0, m_height = 0;
  std::string m_shaderError;
  std::chrono::steady_clock::time_point m_retryAt;
};

} // namespace rtlab
