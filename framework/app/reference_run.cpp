#include "app/reference_run.h"

#include "frame/pass_timer.h"
#include "reference/reference.h"
#include "scene/scene_params.h"
#include "util/error.h"

namespace rtlab {

ReferenceInput referenceInput(Renderer& renderer, const ResolvedFrame& frame) {
  // The G-buffer of this frame: the same surface points the GPU shades. Only the G-buffer passes
  // run (the graph culls everything else), whatever techniques are active.
  FrameOutputs outputs;
  outputs.surfaces = true;
  PassTimer timer(TimingMethod::CpuFinish);
  renderer.render(frame.params, frame.options.width, frame.options.height, outputs, timer);
  ReferenceInput input;
  input.surfaces = renderer.readSurfaces();

  // The lights and camera as this frame's parameters set them (a sweep may vary light<N>.* in
  // frame.params without touching frame.scene).
  input.scene = frame.scene;
  applySceneParams(frame.params, input.scene);
  return input;
}

Image renderReferenceFrame(Renderer& renderer, const ResolvedFrame& frame, const std::string& aov, int spp,
                           bool progress) {
  ReferenceStats stats;
  return renderReferenceFrame(renderer, frame, aov, spp, progress, stats);
}

Image renderReferenceFrame(Renderer& renderer, const ResolvedFrame& frame, const std::string& aov, int spp,
                           bool progress, ReferenceStats& stats) {
  if (!isReferenceAov(aov)) usageError("the reference has no AOV '" + aov + "' (choices: visibility, ao, indirect)");
  ReferenceOptions options;
  options.spp = spp;
  options.seed = frame.options.seed;
  options.aoRadius = frame.params.getFloat("ao.radius");
  options.progress = progress;
  if (spp < kReferenceMinSpp || spp > kReferenceMaxSpp)
    usageError("--spp " + std::to_string(spp) + " is out of range " + std::to_string(kReferenceMinSpp) + ".." +
               std::to_string(kReferenceMaxSpp));

  const ReferenceInput input = referenceInput(renderer, frame);
  return renderReference(input.scene, input.surfaces, aov, options, stats);
}

} // namespace rtlab
