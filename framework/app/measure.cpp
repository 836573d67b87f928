#include "app/measure.h"

#include "gl/debug.h"
#include "util/log.h"

namespace rtlab {

FrameStats renderMeasured(Renderer& renderer, const ResolvedFrame& frame, const FrameOutputs& outputs,
                          TimingMethod timing, bool countHdrClamp) {
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
  if (countHdrClamp) {
    FrameOutputs counted = outputs;
    counted.countHdrClamped = true;
    PassTimer untimed(timing);
    renderer.render(frame.params, frame.options.width, frame.options.height, counted, untimed);
    const int errors = drainGlErrors();
    if (errors > 0) logWarn(std::to_string(errors) + " GL errors in the frame that counts the HDR clamp");
    stats.setHdrClamped(renderer.readHdrClamped());
  }
  // After the counting frame: a technique that counts only on such frames (bloom's non-finite and
  // clamped pixels) reports that frame's counts; the others report the same frame again.
  stats.setCounters(renderer.counters());
  if (stats.glErrors() > 0) logWarn(std::to_string(stats.glErrors()) + " GL errors during the measured frames");
  return stats;
}

} // namespace rtlab
