// The arealight stage's reference (docs/measuring.md "References per stage"): `rtlab reference
// --aov arealight [--spp N]` estimates the integral of docs/contract.md "Area lights" per pixel on
// the CPU from the frame's surface points and the G-buffer's material, light-area sampling and GGX
// sampling combined with the power heuristic (area_mc_model.h). It shares the estimator's
// definition with the GPU technique, none of its passes.
#include "reference/reference_registry.h"
#include "techniques/area_mc/area_mc_model.h"

#include <chrono>

namespace rtlab {

void registerReference_area_mc(ReferenceRegistry& registry) {
  ReferenceEntry e;
  e.aov = "arealight";
  e.stage = "arealight";
  e.help = "radiance of the rectangular lights, unshadowed, frame BRDF (MIS Monte-Carlo per pixel)";
  e.channels = 3;
  e.inputs = {FrameInput::SurfacePoints};
  e.keys = {"light<N>.", "camera."};
  e.minSpp = 1;
  e.maxSpp = 131072;
  e.defaultSpp = 1024;
  e.compute = [](const ReferenceFrame& frame, ReferenceStats& stats) {
    const auto start = std::chrono::steady_clock::now();
    area_mc::ReferenceJob job;
    job.spp = frame.spp();
    job.seed = frame.seed();
    job.progress = frame.progress();
    job.cancel = frame.cancelFlag();
    job.threads = frame.threads();
    Image out = area_mc::renderArealightReference(frame.scene(), frame.surfaces(), job);
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
  };
  registry.add(std::move(e));
}

} // namespace rtlab
