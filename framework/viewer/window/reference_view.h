// Compare mode's ground truth in the viewer: the progressive Embree reference of the active
// stage's AOV (reference/progressive_reference.h), refined on a worker thread while the view is
// still and restarted whenever something it depends on changes (scene, lights, camera,
// ao.radius, render size, AOV); the UI never waits for it. Each new batch is uploaded for the
// wipe and the difference view, and the live metrics of the visible frame's AOV against it are
// computed as `rtlab compare` computes them (reference/live_metrics.h: from 16 spp on). A restart
// after a camera or light change reuses the reference's BVH; a new scene builds it again.
#pragma once
#include "gl/texture.h"
#include "reference/progressive_reference.h"
#include "render/renderer.h"
#include "viewer/viewer_state.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rtlab {

// The stage AOV compare mode shows: the debug view's AOV when it is a reference AOV and shown,
// else the output of the first of shadow, ao, indirect with an active technique, else visibility.
std::string referenceAovFor(const ViewerState& state);

class ReferenceView {
public:
  // After a frame rendered with FrameOutputs{aovs: {aov}, surfaces: true}: restarts the
  // reference if its inputs changed and then held still for a frame (while the camera or a light
  // is being dragged it is only cancelled), takes the latest batch, updates state.reference, and
  // measures the frame against it when the frame's parameters held still for a frame.
  void update(ViewerState& state, Renderer& renderer, unsigned seed, int width, int height);
  // Stops refining (compare mode off); does not wait for the worker.
  void stop(ViewerState& state);
  // The reference's current mean (RGBA32F; alpha = mask), or nullptr before the first batch.
  const gl::Texture* texture() const { return m_texture ? &m_texture : nullptr; }
  int channels() const { return m_snapshot.image.channels; }

private:
  // The cheap inputs the reference's key is built from: the key is built again only when they move.
  struct KeyInputs {
    unsigned long sceneGeneration = ~0ul, paramsRevision = ~0ul;
    int width = 0, height = 0;
    std::string aov;
    bool operator==(const KeyInputs&) const = default;
  };
  // What the metrics were last computed from.
  struct MetricsInputs {
    std::uint64_t generation = 0;
    int bucket = -1;
    unsigned long paramsRevision = ~0ul;
    std::vector<std::string> techniques;
    bool operator==(const MetricsInputs&) const = default;
  };
  void restart(ViewerState& state, Renderer& renderer, unsigned seed, const std::string& aov);
  void measure(ViewerState& state, Renderer& renderer, int width, int height, const std::string& aov);

  ProgressiveReference m_reference;
  ProgressiveSnapshot m_snapshot;
  gl::Texture m_texture;
  KeyInputs m_keyInputs;
  std::string m_key;                      // everything the reference depends on, for m_keyInputs
  std::string m_startedKey;               // what the running reference was started from
  std::string m_settlingKey;              // new inputs seen last frame, not started yet
  unsigned long m_sceneGeneration = ~0ul; // the scene the reference's BVH was built for
  MetricsInputs m_metrics;
  unsigned long m_lastRevision = ~0ul; // the parameters' revision in the previous frame
  bool m_active = false;
};

} // namespace rtlab
