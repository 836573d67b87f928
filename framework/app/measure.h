// Renders a resolved frame the way every command measures it: 2 warm-up frames when more than
// one frame is measured (docs/contract.md --frames), GL errors counted per frame, resources recorded.
// With `countHdrClamp` (the caller writes stats), one more frame, untimed, counts the HDR clamp's
// pixels (docs/stages.md "The HDR clamp"): the counting shaders are slower, so no timed frame counts.
// With `exposure`, the exposure readout (image/exposure.h) of the last measured frame's `color` goes
// into the stats, computed on the CPU after the measured frames; when the outputs lack the `color`
// AOV, one more untimed frame (before the counting one) renders them with it.
#pragma once
#include "app/frame_options.h"
#include "frame/stats.h"
#include "render/renderer.h"

namespace rtlab {

FrameStats renderMeasured(Renderer& renderer, const ResolvedFrame& frame, const FrameOutputs& outputs,
                          TimingMethod timing, bool countHdrClamp, bool exposure = false);

} // namespace rtlab
