// Live metrics of the viewer's frame against the progressive reference (live_metrics.h).
#include "reference/live_metrics.h"

#include "util/error.h"

namespace rtlab {

bool liveReferenceReady(const ProgressiveSnapshot& reference, int width, int height, const LiveMetricsPolicy& policy,
                        std::string* reason) {
  if (policy.minSamples < kReferenceMinSpp || policy.minSamples > kReferenceMaxSpp)
    usageError("live metrics minSamples " + std::to_string(policy.minSamples) + " is out of range " +
               std::to_string(kReferenceMinSpp) + ".." + std::to_string(kReferenceMaxSpp));
  std::string why;
  if (reference.generation == 0 || reference.image.pixels.empty())
    why = "no reference yet";
  else if (reference.samples < policy.minSamples)
    why = "reference has " + std::to_string(reference.samples) + " of " + std::to_string(policy.minSamples) + " spp";
  else if (reference.image.width != width || reference.image.height != height)
    why = "reference is " + std::to_string(reference.image.width) + "x" + std::to_string(reference.image.height) +
          ", frame is " + std::to_string(width) + "x" + std::to_string(height);
  if (reason) *reason = why;
  return why.empty();
}

LiveMetrics computeLiveMetrics(const Image& frame, const ProgressiveSnapshot& reference,
                               const LiveMetricsPolicy& policy) {
  LiveMetrics live;
  live.referenceSamples = reference.samples;
  live.generation = reference.generation;
  live.ready = liveReferenceReady(reference, frame.width, frame.height, policy, &live.reason);
  // As `rtlab compare REFERENCE.exr FRAME.exr`: A the reference, B the frame, EXR conventions.
  if (live.ready) live.metrics = computeMetrics(reference.image, frame, MetricsOptions{});
  return live;
}

} // namespace rtlab
