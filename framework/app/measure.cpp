#include "app/measure.h"

#include "gl/debug.h"
#include "image/exposure.h"
#include "util/log.h"

#include <algorithm>

namespace rtlab {

FrameStats renderMeasured(Renderer& renderer, const ResolvedFrame& frame, const FrameOutputs& outputs,
                          TimingMethod timing, bool countHdrClamp, bool exposure) {
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
  if (exposure) {
    // Before the counting frame, so that the last frame still has exactly the caller's outputs.
    if (std::find(outputs.aovs.begin(), outputs.aovs.end(), "color") == outputs.aovs.end()) {
      FrameOutputs withColor = outputs;
      withColor.aovs.push_back("color");
      PassTimer untimed(timing);
      renderer.render(frame.params, frame.options.width, frame.options.height, withColor, untimed);
      const int errors = drainGlErrors();
      if (errors > 0) logWarn(std::to_string(errors) + " GL errors in the frame that measures the exposure");
    }
    stats.setExposure(measureExposure(renderer.readAov("color")));
  }
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
