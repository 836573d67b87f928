// The viewer's live error figures (issue 5, "Compare mode"): the current frame's AOV against the
// progressive reference's latest mean, with exactly the metrics and conventions of
// `rtlab compare REFERENCE.exr FRAME.exr` (image/metrics.h): the reference is A, the frame is B,
// valid pixels are finite in both and masked 1 where an image has a mask, and values are read as
// linear data (MetricsOptions defaults, as for EXR files). docs/progressive-reference.md.
//
// The ready policy: a noisy reference inflates the measured error (the reference's own variance
// adds to the MSE), so figures are reported only once the reference holds at least
// `minSamples` samples per pixel (16 by default: the reference's standard error is then a quarter
// of one sample's) and matches the frame's size. Before that, ready is false and `reason` says
// why, so the UI can show "reference: 8 / 16 spp".
#pragma once
#include "image/image.h"
#include "image/metrics.h"
#include "reference/progressive_reference.h"

#include <cstdint>
#include <string>

namespace rtlab {

struct LiveMetricsPolicy {
  int minSamples = 16; // 1..kReferenceMaxSpp; figures appear once the reference has this many spp
};

struct LiveMetrics {
  bool ready = false;           // metrics hold figures (see the ready policy above)
  std::string reason;           // why not ready (empty when ready)
  int referenceSamples = 0;     // of the snapshot measured against
  std::uint64_t generation = 0; // of the snapshot measured against
  Metrics metrics;              // computeMetrics(reference, frame) when ready
};

// Whether `reference` may be measured against a frame of width x height under `policy`; when it
// may not, `reason` (may be null) says why. Error(Usage) for minSamples out of range.
bool liveReferenceReady(const ProgressiveSnapshot& reference, int width, int height, const LiveMetricsPolicy& policy,
                        std::string* reason = nullptr);

// The frame's AOV (Renderer::readAov: float, mask from coverage) against the snapshot. The frame
// and reference may differ in channel count (compare's luminance rule applies). FLIP is the cost:
// call this when latest() brought a new snapshot or the frame changed, not on every redraw.
LiveMetrics computeLiveMetrics(const Image& frame, const ProgressiveSnapshot& reference,
                               const LiveMetricsPolicy& policy = {});

} // namespace rtlab
