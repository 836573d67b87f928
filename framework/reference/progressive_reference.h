// The viewer's ground truth: the CPU reference of one stage AOV (reference.h) refined in the
// background, batch after batch, so that a window can show it while it converges (issue 5,
// "Compare mode"; docs/progressive-reference.md). start() never blocks: it cancels the job in
// progress (if any) and returns; a worker thread then accumulates independent batches of samples
// (1, 1, 2, 4, ... spp per pixel, capped by batchMaxSpp) into a running mean until targetSpp is
// reached. latest() hands the UI a copy of the current mean when a batch has completed since the
// caller's last copy.
//
// Cancellation is prompt: a restart, stop() or the destructor stops the worker within one tile of
// work (16x16 pixels at one batch's sample count). The worker runs its ray casting in a TBB arena
// of `threads` threads so that a software rasterizer sharing the machine keeps a core.
//
// The BVH: start(scene, ...) copies the scene and the worker builds its BVH; preparedScene() then
// returns it, and start(prepared, scene, ...) reuses it, so that a restart after a camera move or
// a light edit does not rebuild it (prepared_scene.h says when it must be rebuilt).
#pragma once
#include "image/image.h"
#include "reference/prepared_scene.h"
#include "reference/reference.h"
#include "reference/surfaces.h"
#include "scene/scene.h"

#include <cstdint>
#include <memory>
#include <string>

namespace rtlab {

struct ProgressiveOptions {
  int targetSpp = 1024;  // stop refining at this many samples per pixel (kReferenceMinSpp..kReferenceMaxSpp)
  int batchMaxSpp = 16;  // largest batch, 1..kReferenceMaxSpp: bounds the time between two snapshots
  unsigned seed = 1;     // batch k uses a seed derived from (seed, k): batches are independent
  float aoRadius = 0.5f; // ao.radius
  int threads = 0;       // 0: max(1, hardware threads - 1); otherwise 1..1024
};

struct ProgressiveSnapshot {
  Image image;                  // the mean so far (channels and mask as renderReference)
  int samples = 0;              // samples per pixel accumulated in `image`
  std::uint64_t generation = 0; // which start() it belongs to (1 for the first)
  bool converged = false;       // samples == targetSpp
};

// The sample count of batch k (0-based) of a job: 1, 1, 2, 4, ... capped by batchMaxSpp and by
// what is left to reach targetSpp after `done` samples.
int progressiveBatchSpp(int k, int done, const ProgressiveOptions& options);
// The seed of batch k: a hash of (seed, k), so that batches are independent of one another.
unsigned progressiveBatchSeed(unsigned seed, int k);

class ProgressiveReference {
public:
  ProgressiveReference();
  ~ProgressiveReference(); // cancels and joins
  ProgressiveReference(const ProgressiveReference&) = delete;
  ProgressiveReference& operator=(const ProgressiveReference&) = delete;

  // Cancels any job in progress and starts refining `aov` ("visibility", "ao", "indirect") of
  // these surfaces, seen from scene.camera.position and lit by scene.lights. Returns the new
  // generation. Invalid input (unknown AOV, no light for visibility, aoRadius <= 0, targetSpp or
  // batchMaxSpp outside the reference's range, threads < 0) throws Error(Usage) here,
  // synchronously, and leaves the previous job cancelled (and the generation unchanged).
  // This overload copies `scene` (the caller may change it right after) and the worker builds the
  // BVH before the first batch.
  std::uint64_t start(const Scene& scene, SurfaceData surfaces, const std::string& aov,
                      const ProgressiveOptions& options);
  // The same on a prepared scene (BVH built): only the lights and the camera position are taken
  // from `scene`; geometry and materials come from `prepared`, which must hold the same ones. A
  // null `prepared` behaves as the overload above.
  std::uint64_t start(std::shared_ptr<const PreparedReferenceScene> prepared, const Scene& scene, SurfaceData surfaces,
                      const std::string& aov, const ProgressiveOptions& options);
  // Cancels the job in progress (if any) and waits for the worker to stop: at most one tile, or
  // the BVH build in progress (Embree cannot interrupt it).
  void stop();
  // Cancels the job in progress (if any) without waiting: the worker stops within one tile (or
  // after the BVH build in progress) on its own. running() is false from now on.
  void cancel();

  // If a batch of the current generation completed since `out` was filled (another generation,
  // or more samples), copies the current mean into `out` and returns true; otherwise leaves `out`
  // alone and returns false. After a start(), nothing is returned until the new job's first batch
  // completes (the previous mean is dropped: it belongs to another view); compare
  // out.generation with generation() to tell whether a held snapshot is current.
  bool latest(ProgressiveSnapshot& out) const;
  // Cheap status for the UI.
  int samples() const;              // samples per pixel of the current generation's mean
  std::uint64_t generation() const; // of the last successful start(); 0 before
  bool running() const;             // a job is pending or refining (false once converged, stopped or failed)
  // The last worker error (an exception from the tracer), empty when none; cleared by start().
  std::string error() const;
  // The prepared scene of the current job once its worker has built it (or the one start() was
  // given), also when the job was cancelled or stopped after the build began; null before.
  std::shared_ptr<const PreparedReferenceScene> preparedScene() const;

private:
  struct State;
  std::shared_ptr<State> m_state;
};

} // namespace rtlab
