#include "app/reference_run.h"

#include "frame/pass_timer.h"
#include "frame/registry.h"
#include "scene/scene_params.h"
#include "util/error.h"

namespace rtlab {
namespace {

// The frame's techniques outside the reference's own stage: the colour before post is what they
// produce (the stage being measured is what the reference replaces).
std::vector<std::string> techniquesBefore(const ResolvedFrame& frame, const ReferenceEntry& reference) {
  std::vector<std::string> ids;
  for (const auto& id : frame.techniques)
    if (TechniqueRegistry::instance().get(id).info.stage != reference.stage) ids.push_back(id);
  return ids;
}

} // namespace

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

Image renderReferenceFrame(Renderer& renderer, const ResolvedFrame& frame, const ReferenceEntry& reference, int spp,
                           bool progress, ReferenceStats& stats) {
  if (spp < reference.minSpp || spp > reference.maxSpp)
    usageError("--spp " + std::to_string(spp) + " is out of range " + std::to_string(reference.minSpp) + ".." +
               std::to_string(reference.maxSpp) + " for the " + reference.aov + " reference");
  const Scene scene = sceneForReference(frame.scene, frame.params, reference);
  ReferenceFrame input(reference, scene, frame.params, spp, frame.options.seed, progress);

  SurfaceData surfaces;
  Image prePost, opaque;
  const bool readsColor = reference.inputs.has(FrameInput::PrePostColor);
  const bool readsFragments = reference.inputs.has(FrameInput::TransparentFragments);
  if (reference.inputs.has(FrameInput::SurfacePoints) || readsColor || readsFragments) {
    if (readsColor || readsFragments) renderer.setTechniques(techniquesBefore(frame, reference));
    FrameOutputs outputs;
    outputs.surfaces = reference.inputs.has(FrameInput::SurfacePoints);
    if (readsColor) outputs.colors.push_back(kPrePostColorVersion);
    if (readsFragments) {
      outputs.colors.push_back(kOpaqueColorVersion);
      outputs.transparentFragments = true;
    }
    PassTimer timer(TimingMethod::CpuFinish);
    renderer.render(frame.params, frame.options.width, frame.options.height, outputs, timer);
    if (outputs.surfaces) {
      surfaces = renderer.readSurfaces();
      input.setSurfaces(&surfaces);
    }
    if (readsColor) {
      prePost = renderer.readColor(kPrePostColorVersion);
      input.setPrePostColor(&prePost);
    }
    if (readsFragments) {
      opaque = renderer.readColor(kOpaqueColorVersion);
      input.setTransparentFragments(&renderer.readTransparentFragments(), &opaque);
    }
  }
  return reference.compute(input, stats);
}

Image renderReferenceFrame(Renderer& renderer, const ResolvedFrame& frame, const std::string& aov, int spp,
                           bool progress) {
  ReferenceStats stats;
  return renderReferenceFrame(renderer, frame, aov, spp, progress, stats);
}

Image renderReferenceFrame(Renderer& renderer, const ResolvedFrame& frame, const std::string& aov, int spp,
                           bool progress, ReferenceStats& stats) {
  return renderReferenceFrame(renderer, frame, ReferenceRegistry::instance().get(aov), spp, progress, stats);
}

} // namespace rtlab
