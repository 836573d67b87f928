// Compare mode's ground truth in the viewer (docs/viewer.md "Compare mode"), one of two kinds:
// - the progressive Embree reference of visibility, ao or indirect
//   (reference/progressive_reference.h), refined on a worker thread while the view is still and
//   restarted whenever something it depends on changes (scene, lights, camera, ao.radius, render
//   size, AOV). Each new batch is uploaded; live metrics from 16 spp on. A restart after a camera
//   or light change reuses the reference's BVH; a new scene builds it again.
// - any other registered reference (reference/reference_registry.h; the post stage's `bloom`),
//   computed once on a worker thread (viewer/reference_job.h) from what it reads back from the
//   frame (the colour before post, the surface points), and computed again when anything it
//   depends on changes: the scene, the render size, the AOV, every key referenceDependsOnKey
//   names and the techniques of the other stages. Exact (no samples) when the reference does not
//   sample; live metrics as soon as it is there.
// The UI never waits for either; the live metrics of the visible frame's AOV against the
// reference are computed as `rtlab compare` computes them (reference/live_metrics.h).
#pragma once
#include "gl/texture.h"
#include "reference/progressive_reference.h"
#include "render/renderer.h"
#include "viewer/reference_job.h"
#include "viewer/viewer_state.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace rtlab {

// The AOV compare mode shows: the debug view's AOV when it is shown and has a registered
// reference; else, in frame order (shadow, ao, indirect, ..., post), the reference AOV of the first
// stage that has one and an active technique producing that AOV; else visibility.
std::string referenceAovFor(const ViewerState& state);
// Whether compare mode refines `aov`'s reference progressively (visibility, ao, indirect) rather
// than computing it once (ReferenceJob).
bool isProgressiveReferenceAov(const std::string& aov);
// Adds to `outputs` what the frame must keep for `aov`'s reference to be read back: the surface
// points (the progressive ones, or a reference declaring them) and the colour before post.
void addReferenceInputs(const std::string& aov, FrameOutputs& outputs);

class ReferenceView {
public:
  // After a frame rendered with the AOV and addReferenceInputs(aov): restarts the reference if its
  // inputs changed and then held still for a frame (while the camera, a light or a key it depends
  // on is being dragged it is only cancelled), takes the latest batch or result, updates
  // state.reference, and measures the frame against it when the frame's parameters held still for
  // a frame.
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
    std::vector<std::string> techniques; // a one-shot reference depends on the other stages' techniques
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
  std::string keyFor(const ViewerState& state, unsigned seed, int width, int height, const std::string& aov) const;
  void cancel();
  void restart(ViewerState& state, Renderer& renderer, unsigned seed, const std::string& aov);
  void restartProgressive(ViewerState& state, Renderer& renderer, unsigned seed, const std::string& aov);
  void restartOneShot(ViewerState& state, Renderer& renderer, unsigned seed, const std::string& aov);
  // TransparentFragments: the frame's transparent fragments and the opaque colour under them, from
  // a frame of the capture renderer (its own Renderer, so that the window's frame, its textures
  // and its last passes stay as they are), with the techniques outside the transparency stage.
  void captureTransparency(ViewerState& state, const ReferenceEntry& entry, ReferenceJobInput& input);
  // Takes the running reference's latest batch or result into m_snapshot (uploaded); false while
  // nothing of the current generation is there.
  bool takeLatest(ViewerState& state);
  void measure(ViewerState& state, Renderer& renderer, int width, int height, const std::string& aov);

  ProgressiveReference m_reference;
  ReferenceJob m_job;
  bool m_oneShot = false;       // the running reference is m_job's, not m_reference's
  ProgressiveSnapshot m_snapshot; // the latest batch, or the one-shot result (converged)
  gl::Texture m_texture;
  KeyInputs m_keyInputs;
  std::string m_key;                      // everything the reference depends on, for m_keyInputs
  std::string m_startedKey;               // what the running reference was started from
  std::string m_settlingKey;              // new inputs seen last frame, not started yet
  unsigned long m_sceneGeneration = ~0ul; // the scene the reference's BVH was built for
  MetricsInputs m_metrics;
  unsigned long m_lastRevision = ~0ul; // the parameters' revision in the previous frame
  bool m_active = false;
  std::unique_ptr<Renderer> m_captureRenderer;
  unsigned long m_captureScene = ~0ul; // the scene generation m_captureRenderer holds
  int m_width = 0, m_height = 0;       // the frame size of the last update()
};

} // namespace rtlab
