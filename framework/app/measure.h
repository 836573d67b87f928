// Renders a resolved frame the way every command measures it: 2 warm-up frames when more than
// one frame is measured (docs/contract.md --frames), GL errors counted per frame, resources and the
// last frame's HDR clamp counts recorded.
#pragma once
#include "app/frame_options.h"
#include "frame/renderer.h"
#include "frame/stats.h"

namespace rtlab {

FrameStats renderMeasured(Renderer& renderer, const ResolvedFrame& frame, const FrameOutputs& outputs,
                          TimingMethod timing);

} // namespace rtlab
