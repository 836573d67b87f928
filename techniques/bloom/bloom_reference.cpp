// The post stage's reference (docs/measuring.md "References per stage"): `rtlab reference --aov
// bloom` convolves the frame's own colour before the post stage with the declared PSF, exactly
// (double precision, separable, outside the frame black) on the CPU — bloom_model.h convolve().
// It shares the definition of the bright pass and the PSF with the technique, none of its passes.
#include "reference/reference_registry.h"
#include "techniques/bloom/bloom_model.h"

#include <chrono>

namespace rtlab {

void registerReference_bloom(ReferenceRegistry& registry) {
  ReferenceEntry e;
  e.aov = "bloom";
  e.stage = "post";
  e.help = "intensity x (soft-knee bright pass of the colour before post, convolved with the PSF)";
  e.channels = 3;
  e.inputs = {FrameInput::PrePostColor};
  e.keys = {"bloom.threshold", "bloom.knee", "bloom.intensity", "bloom.sigma", "bloom.octaves", "bloom.hard_cut"};
  e.compute = [](const ReferenceFrame& frame, ReferenceStats& stats) {
    const auto start = std::chrono::steady_clock::now();
    bloom::Definition d;
    d.threshold = frame.getFloat("bloom.threshold");
    d.knee = frame.getFloat("bloom.knee");
    d.intensity = frame.getFloat("bloom.intensity");
    d.sigma = frame.getFloat("bloom.sigma");
    d.octaves = int(frame.getFloat("bloom.octaves"));
    d.hardCut = frame.getFloat("bloom.hard_cut") != 0.0f;
    Image out = bloom::convolve(bloom::brightPass(frame.prePostColor(), d), d, frame.threads(), frame.cancelFlag());
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
  };
  registry.add(std::move(e));
}

} // namespace rtlab
