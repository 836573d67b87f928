// Renders a resolved frame the way every command measures it: 2 warm-up frames when more than
// one frame is measured (docs/contract.md --frames), GL errors counted per frame, resources recorded.
// With `countHdrClamp` (the caller writes stats), one more frame, untimed, counts the HDR clamp's
// pixels (docs/stages.md "The HDR clamp"): the counting shaders are slower, so no timed frame counts.
#pragma once
#include "app/frame_options.h"
#include "frame/stats.h"
#include "render/renderer.h"

namespace rtlab {

FrameStats renderMeasured(Renderer& renderer, const ResolvedFrame& frame, const FrameOutputs& outputs,
                          TimingMethod timing, bool countHdrClamp);

} // namespace rtlab
