// The reference of one resolved frame: renders the frame's G-buffer with `renderer` (so the
// surface points are the GPU's), reads the surfaces back and runs the CPU reference on them.
// Shared by `rtlab reference` and `rtlab sweep`.
#pragma once
#include "app/frame_options.h"
#include "image/image.h"
#include "reference/reference.h"
#include "render/renderer.h"

#include <string>

namespace rtlab {

// What the reference of a frame starts from: the surface points of the frame's G-buffer (rendered
// with `renderer`, which must hold frame.scene) and the scene with the lights and camera as
// frame.params set them. Shared by renderReferenceFrame and the progressive-reference benchmark.
struct ReferenceInput {
  Scene scene;
  SurfaceData surfaces;
};
ReferenceInput referenceInput(Renderer& renderer, const ResolvedFrame& frame);

// aov: visibility | ao | indirect (Error(Usage) otherwise). ao.radius comes from frame.params;
// the seed from frame.options.seed.
// The renderer must hold frame.scene (Renderer::setScene); its active techniques do not matter.
Image renderReferenceFrame(Renderer& renderer, const ResolvedFrame& frame, const std::string& aov, int spp,
                           bool progress);
// The same, also reporting rays cast and time spent ray casting.
Image renderReferenceFrame(Renderer& renderer, const ResolvedFrame& frame, const std::string& aov, int spp,
                           bool progress, ReferenceStats& stats);

} // namespace rtlab
