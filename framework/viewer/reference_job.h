// Compare mode's ground truth for a reference the progressive worker does not refine
// (docs/viewer.md "Compare mode"): any registered reference (reference/reference_registry.h),
// computed once by its own compute function on a worker thread, from the inputs the viewer read
// back from its frame. For a reference that does not sample (the post stage's `bloom`: an exact
// convolution of the colour before post) the result is exact and complete at once; one that
// samples is computed at its default sample count.
//
// start() never blocks: it replaces the pending job (if any), tells a computation in progress
// that it is superseded (ReferenceFrame::cancelled: a compute function checks it and stops within
// a moment; bloom's per row), and returns; the superseded result is dropped, and only the newest
// pending job runs next (those in between never run). cancel() and the destructor stop a
// computation the same way; the destructor then joins the worker. The computation uses all cores
// but one. GL-free: the viewer uploads the result (window/reference_view.h).
#pragma once
#include "image/image.h"
#include "params/param_set.h"
#include "reference/reference_registry.h"
#include "reference/surfaces.h"
#include "scene/scene.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace rtlab {

// Everything one computation reads: a copy, so the caller may change its state right after start().
struct ReferenceJobInput {
  ReferenceEntry entry; // a copy of the registered entry (its compute function included)
  Scene scene;          // as the reference may see it (sceneForReference, reference/reference_registry.h)
  ParamSet params;      // the frame's parameters
  int spp = 1;          // entry.minSpp..entry.maxSpp
  unsigned seed = 1;
  std::optional<SurfaceData> surfaces; // when the entry declares FrameInput::SurfacePoints
  std::optional<Image> prePostColor;   // when the entry declares FrameInput::PrePostColor
  std::optional<CapturedFragments> transparentFragments; // with opaqueColor: FrameInput::TransparentFragments
  std::optional<Image> opaqueColor;
};

struct ReferenceJobResult {
  Image image;
  std::uint64_t generation = 0; // which start() it belongs to (1 for the first); 0: none
  int samples = 0;              // the spp it was computed at
  double seconds = 0.0;         // wall time of the compute function
};

class ReferenceJob {
public:
  ReferenceJob();
  ~ReferenceJob(); // drops the pending job, cancels a computation in progress and waits for it to stop
  ReferenceJob(const ReferenceJob&) = delete;
  ReferenceJob& operator=(const ReferenceJob&) = delete;

  // Queues a computation and returns its generation at once. Error(Internal) when the input
  // lacks what the entry declares (surfaces, colour before post), Error(Usage) for an spp outside
  // the entry's range; the queue is left as it was then.
  std::uint64_t start(ReferenceJobInput input);
  // Drops the pending job and cancels the one computing (not waited for); running() is false from
  // now on.
  void cancel();

  // If the current generation's result is ready and `out` does not hold it yet, moves a copy into
  // `out` and returns true; otherwise leaves `out` alone and returns false.
  bool latest(ReferenceJobResult& out) const;
  std::uint64_t generation() const; // of the last start(); 0 before
  bool running() const;             // the current generation is pending or computing
  std::string error() const;        // the current generation's failure (the compute threw); else empty

private:
  struct State;
  std::shared_ptr<State> m_state;
};

} // namespace rtlab
