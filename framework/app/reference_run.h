// The reference of one resolved frame (docs/measuring.md "References per stage"): renders what the
// registered reference declares as its inputs with `renderer` (the G-buffer's surface points, the
// colour before post), reads them back and runs the reference's compute function on them.
// Shared by `rtlab reference` and `rtlab sweep`.
#pragma once
#include "app/frame_options.h"
#include "image/image.h"
#include "reference/reference.h"
#include "reference/reference_registry.h"
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

// Runs `reference` on the frame: spp in the reference's range (Error(Usage) otherwise), the seed
// from frame.options.seed, parameters from frame.params. The renderer must hold frame.scene
// (Renderer::setScene); it renders the frame's techniques of the other stages only when the
// reference reads the colour before post.
Image renderReferenceFrame(Renderer& renderer, const ResolvedFrame& frame, const ReferenceEntry& reference, int spp,
                           bool progress, ReferenceStats& stats);
// The same for the registered reference of `aov` (Error(Usage) naming the choices for another).
Image renderReferenceFrame(Renderer& renderer, const ResolvedFrame& frame, const std::string& aov, int spp,
                           bool progress);
Image renderReferenceFrame(Renderer& renderer, const ResolvedFrame& frame, const std::string& aov, int spp,
                           bool progress, ReferenceStats& stats);

} // namespace rtlab
