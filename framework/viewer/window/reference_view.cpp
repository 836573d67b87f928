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
  if (!m_active) return;
  m_reference.stop();
  m_active = false;
  m_inputsKey.clear();
  m_metricsKey.clear();
  state.reference.running = false;
}

void ReferenceView::update(ViewerState& state, Renderer& renderer, unsigned seed, int width, int height) {
  const std::string aov = referenceAovFor(state);
  // Everything the reference depends on; technique parameters are not in it (they change the
  // frame, not the ground truth).
  const std::string inputsKey = state.sceneSpec + "|" + aov + "|" + std::to_string(width) + "x" +
                                std::to_string(height) + "|" +
                                state.params.toJson({"light", "camera.", "ao.radius"}).dump();
  auto& status = state.reference;
  if (inputsKey != m_inputsKey) {
    m_inputsKey = inputsKey;
    m_metricsKey.clear();
    m_snapshot = ProgressiveSnapshot{};
    m_texture.reset();
    status = {};
    status.aov = aov;
    try {
      ProgressiveOptions options;
      options.seed = seed;
      options.aoRadius = state.params.getFloat("ao.radius");
      Scene scene = state.scene;
      applySceneParams(state.params, scene);
      auto prepared = m_reference.preparedScene();
      if (prepared && m_sceneGeneration == state.sceneGeneration)
        m_reference.start(prepared, scene, renderer.readSurfaces(), aov, options);
      else
        m_reference.start(scene, renderer.readSurfaces(), aov, options);
      m_sceneGeneration = state.sceneGeneration;
      m_active = true;
    } catch (const Error& e) {
      status.error = e.what();
      m_active = false;
      return;
    }
  }
  status.running = m_reference.running();
  status.samples = m_reference.samples();
  if (const std::string error = m_reference.error(); !error.empty()) status.error = error;
  if (m_reference.latest(m_snapshot)) uploadImage(m_snapshot.image, m_texture, "viewer.reference");
  if (m_snapshot.generation != m_reference.generation()) return; // nothing of this view yet
  // The metrics follow both the reference and the frame (technique parameters). FLIP costs a
  // frame or more on a loaded CPU, so they are measured again each time the reference's sample
  // count reaches the next power of two (16, 32, 64, ...), not after every batch.
  int bucket = 0;
  while ((2 << bucket) <= m_snapshot.samples)
    ++bucket;
  std::string metricsKey = std::to_string(m_snapshot.generation) + "/" + std::to_string(bucket) + "/" +
                           std::to_string(state.params.revision());
  for (const auto& id : state.selection.ordered())
    metricsKey += "/" + id;
  if (metricsKey == m_metricsKey) return;
  m_metricsKey = metricsKey;
  const LiveMetrics live = computeLiveMetrics(renderer.readAov(aov), m_snapshot);
  status.waiting = live.reason;
  if (!live.ready) return;
  status.rmse = live.metrics.rmse;
  status.flip = live.metrics.flip;
  status.metricsSamples = live.referenceSamples;
}

} // namespace rtlab
