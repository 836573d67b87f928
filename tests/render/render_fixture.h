// One headless GL context for the whole render-test binary (programs cost 0.1-0.4 s each to JIT
// on llvmpipe, so they are shared through one Renderer per scene set-up where possible).
#pragma once
#include "app/frame_options.h"
#include "params/param_set.h"
#include "platform/context.h"
#include "render/renderer.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace rtlab {

Context& testContext();

// A scene, its parameters and techniques, rendered in the shared context.
struct TestFrame {
  Scene scene;
  ParamSet params;
  std::vector<std::string> techniques;
  int width = 128, height = 128;
};

// Resolves like the command line: scene name or file, techniques (comma list), KEY=VALUE sets.
TestFrame makeTestFrame(const std::string& scene, const std::string& techniques = "",
                        const std::vector<std::string>& sets = {}, int width = 128, int height = 128);

// Renders one frame of the AOVs (and optionally display color), returns the stats of that frame.
struct TestRender {
  Renderer* renderer = nullptr; // shared per scene name, owned by the fixture
  FrameStats stats;
  int glErrors = 0;
};
TestRender renderTestFrame(const TestFrame& frame, const std::vector<std::string>& aovs, bool displayColor = false,
                           int frames = 1);

// Renders with the shared renderer of the frame's scene name: the scene is uploaded once per name.
// The frame as the command line would resolve it (size, scene, parameters, techniques), for the
// reference renderer (renderReferenceFrame, referenceInput).
ResolvedFrame resolvedOf(const TestFrame& frame);

// Renders one frame with a test's own renderer (a fixture that keeps its scene and parameters):
// makes the context current, activates `techniques`, renders `outputs` at w x h, and expects no GL
// error.
void renderOwnFrame(Renderer& renderer, const ParamSet& params, const std::vector<std::string>& techniques,
                    const FrameOutputs& outputs, int width, int height);
// The value of `technique`'s counter `name` after the last frame (Renderer::counters()); a test
// failure and -1 when there is none.
double techniqueCounter(const Renderer& renderer, const std::string& technique, const std::string& name);

// True if a pool resource of the renderer's last frame has a name starting with `prefix`.
bool hasResource(const Renderer& renderer, const std::string& prefix);
// True if a kept pass of the renderer's last frame has a name starting with `prefix`.
bool ranPass(const Renderer& renderer, const std::string& prefix);

// Destroys the shared renderers (before the context goes).
void releaseTestRenderers();

// Pixel of a world point in a top-to-bottom image of the frame's camera, or false if off-screen.
bool projectToPixel(const TestFrame& frame, const glm::vec3& world, int& x, int& y);

} // namespace rtlab
