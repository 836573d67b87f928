// What every arealight technique ends with (docs/stages.md "The arealight stage"): its frame
// resource `arealight` (the radiance the rectangular lights add, rgb, 0 on background) added to the
// colour it is handed, and the emitting faces of the rectangular lights drawn where the camera sees
// them in front of the surface (shaders/common/rect_face.glsl). The lighting pass leaves both to the
// technique while one runs (SKIP_RECT_LIGHTS), so neither is counted twice.
#pragma once
#include "frame/frame_graph.h"

#include <string>

namespace rtlab {

// The frame resource every arealight technique writes: the stage's AOV reads it.
inline constexpr const char* kArealightResource = "arealight";

// Adds the pass "<technique>.composite": reads frame.colorInput(), `arealight`, and the G-buffer's
// position and coverage; writes frame.colorOutput() = input + arealight, or the face's L_e where a
// face is in front (alpha kept: the face is not a surface).
void addArealightComposite(FrameGraph& frame, const std::string& technique);

} // namespace rtlab
