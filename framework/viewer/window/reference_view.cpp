#include "viewer/window/reference_view.h"

#include "frame/stages.h"
#include "reference/live_metrics.h"
#include "reference/reference.h"
#include "scene/scene_params.h"
#include "util/error.h"
#include "viewer/window/frame_display.h"

namespace rtlab {

std::string referenceAovFor(const ViewerState& state) {
  if (state.view.mode != DebugMode::Off && isReferenceAov(state.view.aov)) return state.view.aov;
  for (const StageInfo& stage : stages()) // in frame order: shadow, ao, indirect
    if (isReferenceAov(stage.output) && !state.selection.activeIn(stage.id).empty()) return stage.output;
  return "visibility";
}

void ReferenceView::stop(ViewerState& state) {
  if (m_active) m_reference.cancel();
  m_active = false;
  if (m_texture) { // a restart would replace them: not kept while compare mode is off
    m_texture.reset();
    m_snapshot = ProgressiveSnapshot{};
  }
  m_startedKey.clear();
  m_settlingKey.clear();
  m_metrics = {};
  state.reference.running = false;
}

void ReferenceView::update(ViewerState& state, Renderer& renderer, unsigned seed, int width, int height) {
  const std::string aov = referenceAovFor(state);
  const unsigned long revision = state.params.revision();
  const bool paramsStill = revision == m_lastRevision;
  m_lastRevision = revision;
  // Everything the reference depends on; technique parameters are not in it (they change the
  // frame, not the ground truth). Built only when a parameter, the scene, the size or the AOV moved.
  KeyInputs inputs{state.sceneGeneration, revision, width, height, aov};
  if (!(inputs == m_keyInputs)) {
    m_keyInputs = std::move(inputs);
    m_key = state.sceneSpec + "|" + aov + "|" + std::to_string(width) + "x" + std::to_string(height) + "|" +
            state.params.toJson({"light", "camera.", "ao.radius"}).dump();
  }
  if (m_key != m_startedKey) {
    // While the inputs change from frame to frame (the camera or a light being dragged), the old
    // reference is only cancelled and cleared; it restarts, reading the surfaces back once, when
    // they have held still for a frame.
    const bool settled = m_key == m_settlingKey;
    m_settlingKey = m_key;
    if (!settled) {
      if (m_active) m_reference.cancel();
      m_active = false;
      m_snapshot = ProgressiveSnapshot{};
      m_texture.reset();
      m_metrics = {};
      state.reference = {};
      state.reference.aov = aov;
      return;
    }
    m_startedKey = m_key;
    restart(state, renderer, seed, aov);
    if (!m_active) return;
  }
  auto& status = state.reference;
  status.running = m_reference.running();
  status.samples = m_reference.samples();
  if (const std::string error = m_reference.error(); !error.empty()) status.error = error;
  if (m_reference.latest(m_snapshot)) uploadImage(m_snapshot.image, m_texture, "viewer.reference");
  if (m_snapshot.generation != m_reference.generation()) return; // nothing of this view yet
  // While a parameter is being dragged the frame changes every frame: it is read back and
  // measured once it holds still.
  if (paramsStill) measure(state, renderer, width, height, aov);
}

void ReferenceView::restart(ViewerState& state, Renderer& renderer, unsigned seed, const std::string& aov) {
  m_metrics = {};
  m_snapshot = ProgressiveSnapshot{};
  m_texture.reset();
  auto& status = state.reference;
  status = {};
  status.aov = aov;
  try {
    ProgressiveOptions options;
    options.seed = seed;
    options.aoRadius = state.params.getFloat("ao.radius");
    // A reused BVH needs only the lights and the camera: the meshes and textures are not copied
    // for a restart after a camera or light change.
    Scene view;
    view.lights = state.scene.lights;
    view.camera = state.scene.camera;
    applySceneParams(state.params, view);
    auto prepared = m_reference.preparedScene();
    if (prepared && m_sceneGeneration == state.sceneGeneration) {
      m_reference.start(prepared, view, renderer.readSurfaces(), aov, options);
    } else {
      Scene scene = state.scene;
      scene.lights = std::move(view.lights);
      scene.camera = view.camera;
      m_reference.start(scene, renderer.readSurfaces(), aov, options);
    }
    m_sceneGeneration = state.sceneGeneration;
    m_active = true;
  } catch (const Error& e) {
    status.error = e.what();
    m_active = false;
  }
}

void ReferenceView::measure(ViewerState& state, Renderer& renderer, int width, int height, const std::string& aov) {
  // The metrics follow both the reference and the frame (technique parameters). FLIP costs a
  // frame or more on a loaded CPU, so they are measured again each time the reference's sample
  // count reaches the next power of two (16, 32, 64, ...), not after every batch.
  int bucket = 0;
  while ((2 << bucket) <= m_snapshot.samples)
    ++bucket;
  MetricsInputs inputs{m_snapshot.generation, bucket, state.params.revision(), state.selection.ordered()};
  if (inputs == m_metrics) return;
  m_metrics = std::move(inputs);
  auto& status = state.reference;
  // Not read back before the reference is good enough to measure against.
  if (!liveReferenceReady(m_snapshot, width, height, LiveMetricsPolicy{}, &status.waiting)) return;
  const LiveMetrics live = computeLiveMetrics(renderer.readAov(aov), m_snapshot);
  status.waiting = live.reason;
  if (!live.ready) return;
  status.rmse = live.metrics.rmse;
  status.flip = live.metrics.flip;
  status.metricsSamples = live.referenceSamples;
}

} // namespace rtlab
