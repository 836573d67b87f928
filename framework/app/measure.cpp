#include "app/measure.h"

#include "gl/debug.h"
#include "util/log.h"

namespace rtlab {

FrameStats renderMeasured(Renderer& renderer, const ResolvedFrame& frame, const FrameOutputs& outputs,
                          TimingMethod timing) {
  renderer.setTechniques(frame.techniques);
  drainGlErrors(); // set-up errors are not a frame's
  PassTimer timer(timing);
  FrameStats stats;
  const int warmup = frame.options.frames > 1 ? 2 : 0;
  for (int i = 0; i < warmup + frame.options.frames; ++i) {
    renderer.render(frame.params, frame.options.width, frame.options.height, outputs, timer);
    const int errors = drainGlErrors();
    if (i >= warmup) stats.addFrame(timer, errors);
  }
  stats.setResources(renderer.resources());
  // Once, after the timed frames: waits for the last frame, which the caller's image readback
  // waits for anyway (docs/stages.md "The HDR clamp").
  stats.setHdrClamped(renderer.readHdrClamped());
  if (stats.glErrors() > 0) logWarn(std::to_string(stats.glErrors()) + " GL errors during the measured frames");
  return stats;
}

} // namespace rtlab
