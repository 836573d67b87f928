// GPU objects every frame shares, owned by the renderer for the context's lifetime: the empty
// vertex array for full-screen triangles, the light buffer (shaders/common/lights.glsl) and the HDR
// clamp counters (shading/hdr_clamp.h).
#pragma once
#include "gl/objects.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "scene/scene.h"
#include "shading/hdr_clamp.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rtlab {

struct GpuCommon {
  static constexpr int kMaxLights = 64; // shaders/common/lights.glsl has the same constant

  gl::VertexArray emptyVao{"fullscreen"};
  gl::Buffer lights;
  int lightCount = 0;
  HdrClampCounters hdrClamp;

  // Uploads the scene's lights into the uniform buffer (created once). Error(Input) for a scene
  // with more than kMaxLights lights.
  void uploadLights(const Scene& scene);
  // Binds the light buffer to binding 0 and sets uLightCount on the program.
  void bindLights(gl::Program& program) const;
  // Draws one full-screen triangle with the currently used program.
  void drawFullscreen() const;
};

// A size x size R16F texture (repeating) of blueNoise(size, seed) from util/sample_patterns.h: the
// per-pixel rotations of the shadow filters and the ao estimators.
gl::Texture makeBlueNoiseTexture(int size, std::uint32_t seed, const std::string& label);

} // namespace rtlab
