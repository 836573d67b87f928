#include "app/reference_run.h"

#include "frame/pass_timer.h"
#include "reference/reference.h"
#include "scene/scene_params.h"
#include "util/error.h"

namespace rtlab {

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

  // The G-buffer of this frame: the same surface points the GPU shades. Only the G-buffer passes
  // run (the graph culls everything else), whatever techniques are active.
  FrameOutputs outputs;
  outputs.surfaces = true;
  PassTimer timer(TimingMethod::CpuFinish);
  renderer.render(frame.params, frame.options.width, frame.options.height, outputs, timer);
  const SurfaceData surfaces = renderer.readSurfaces();

  // The lights and camera as this frame's parameters set them (a sweep may vary light<N>.* in
  // frame.params without touching frame.scene).
  Scene scene = frame.scene;
  applySceneParams(frame.params, scene);
  return renderReference(scene, surfaces, aov, options, stats);
}

} // namespace rtlab
