// Compare mode's ground truth in the viewer: the progressive Embree reference of the active
// stage's AOV (reference/progressive_reference.h), refined on a worker thread while the view is
// still and restarted whenever something it depends on changes (scene, lights, camera,
// ao.radius, render size, AOV); the UI never waits for it. Each new batch is uploaded for the
// wipe and the difference view, and the live metrics of the visible frame's AOV against it are
// computed as `rtlab compare` computes them (reference/live_metrics.h: from 16 spp on). A restart
// after a camera or light change reuses the reference's BVH; a new scene builds it again.
#pragma once
#include "frame/renderer.h"
#include "gl/texture.h"
#include "reference/progressive_reference.h"
#include "viewer/viewer_state.h"

#include <string>

namespace rtlab {

// The stage AOV compare mode shows: the debug view's AOV when it is a reference AOV and shown,
// else the output of the first of shadow, ao, indirect with an active technique, else visibility.
std::string referenceAovFor(const ViewerState& state);

class ReferenceView {
public:
  // After a frame rendered with FrameOutputs{aovs: {aov}, surfaces: true}: restarts the
  // reference if its inputs changed, takes the latest batch, and updates state.reference.
  void update(ViewerState& state, Renderer& renderer, unsigned seed, int width, int height);
  // Stops refining (compare mode off).
  void stop(ViewerState& state);
  // The reference's current mean (RGBA32F; alpha = mask), or nullptr before the first batch.
  const gl::Texture* texture() const { return m_texture ? &m_texture : nullptr; }
  int channels() const { return m_snapshot.image.channels; }

private:
  ProgressiveReference m_reference;
  ProgressiveSnapshot m_snapshot;
  gl::Texture m_texture;
  std::string m_inputsKey;                // what the running reference was started from
  unsigned long m_sceneGeneration = ~0ul; // the scene the reference's BVH was built for
  std::string m_metricsKey;               // what the metrics were computed from
  bool m_active = false;
};

} // namespace rtlab
