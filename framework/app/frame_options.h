// Scene and frame options shared by render, reference, sweep and view (docs/contract.md), and their
// resolution into a scene, a parameter set and the active techniques. Value sources apply in
// order: defaults < --preset < -t < --set.
#pragma once
#include "app/args.h"
#include "app/frame_option_specs.h"
#include "frame/pass_timer.h"
#include "params/param_set.h"
#include "platform/context.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace rtlab {

struct FrameOptions {
  std::string sceneSpec;              // resolved scene argument ("contact" by default)
  int width = 640, height = 360;
  int frames = 1;
  unsigned seed = 1;
  Backend backend = Backend::Auto;
  TimingChoice timing = TimingChoice::Auto;
  std::string savePreset;
};

// Everything a frame needs, resolved and validated, before any GL context exists.
struct ResolvedFrame {
  FrameOptions options;
  Scene scene;
  ParamSet params;
  std::vector<std::string> techniques; // in frame (stage) order
};

// Parses and validates the options, loads the scene and the preset, applies -t and --set in
// command-line order after the preset. Errors: Usage (2) or Input (3).
ResolvedFrame resolveFrame(const Args& args);

// A frame of a scene with techniques (comma list, as -t) and default parameters, for commands
// and tests that set frames up in code.
ResolvedFrame makeResolvedFrame(const std::string& sceneSpec, const std::string& techniques,
                                const FrameOptions& options = {});

// Writes --save-preset if it was given.
void saveRequestedPreset(const ResolvedFrame& frame);

} // namespace rtlab
