// The viewer's ground truth: the CPU reference of one stage AOV (reference.h) refined in the
// background, batch after batch, so that a window can show it while it converges (issue 5,
// "Compare mode"). start() never blocks: it cancels the job in progress (if any) and returns;
// a worker thread then accumulates independent batches of samples (1, 1, 2, 4, ... spp per pixel,
// capped by batchMaxSpp) into a running mean until targetSpp is reached. latest() hands the UI a
// copy of the current mean when a batch has completed since the caller's last copy.
//
// Cancellation is prompt: a restart or the destructor stops the worker within one tile of work.
// The worker runs its ray casting in a TBB arena of `threads` threads so that a software
// rasterizer sharing the machine keeps a core.
#pragma once
#include "image/image.h"
#include "reference/reference.h"
#include "reference/surfaces.h"
#include "scene/scene.h"

#include <cstdint>
#include <memory>
#include <string>

namespace rtlab {

struct ProgressiveOptions {
  int targetSpp = 1024;  // stop refining at this many samples per pixel
  int batchMaxSpp = 16;  // largest batch (keeps a restart's latency bounded)
  unsigned seed = 1;     // batch k uses a seed derived from (seed, k): batches are independent
  float aoRadius = 0.5f; // ao.radius
  int threads = 0;       // 0: max(1, hardware threads - 1)
};

struct ProgressiveSnapshot {
  Image image;                  // the mean so far (channels and mask as renderReference)
  int samples = 0;              // samples per pixel accumulated in `image`
  std::uint64_t generation = 0; // which start() it belongs to (1 for the first)
  bool converged = false;       // samples == targetSpp
};

class ProgressiveReference {
public:
  ProgressiveReference();
  ~ProgressiveReference(); // cancels and joins
  ProgressiveReference(const ProgressiveReference&) = delete;
  ProgressiveReference& operator=(const ProgressiveReference&) = delete;

  // Cancels any job in progress and starts refining `aov` ("visibility", "ao", "indirect") of
  // these surfaces. Returns the new generation. Invalid input (unknown AOV, no light for
  // visibility, aoRadius <= 0, targetSpp outside the reference's range) throws Error(Usage)
  // here, synchronously, and leaves the previous job cancelled.
  std::uint64_t start(const Scene& scene, SurfaceData surfaces, const std::string& aov,
                      const ProgressiveOptions& options);
  // Cancels the job in progress (if any) and waits for the worker to stop.
  void stop();

  // If a batch completed since `out` was filled (another generation, or more samples), copies
  // the current mean into `out` and returns true; otherwise leaves `out` alone, returns false.
  bool latest(ProgressiveSnapshot& out) const;
  // Cheap status for the UI.
  int samples() const;
  std::uint64_t generation() const;
  bool running() const;
  // The last worker error (an exception from the tracer), empty when none.
  std::string error() const;

private:
  struct State;
  std::shared_ptr<State> m_state;
};

} // namespace rtlab
