// Building blocks shared by the shadow-stage techniques: a full-screen pass over the G-buffer that
// reads the stage's depth map and writes a frame-size output, and the filtering kit (tap
// patterns, a blue-noise rotation texture, comparison and raw-depth samplers) for
// shaders/shadow/common/shadow_filter.glsl.
#pragma once
#include "gl/objects.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "params/param_spec.h"

#include <glm/glm.hpp>

#include <functional>
#include <string>
#include <vector>

namespace rtlab {

class FrameGraph;
class PassBuilder;
struct PassContext;

// A full-screen pass of a shadow technique over the G-buffer: fullscreen.vert + `fragment` with
// the light's SHADOW_PROJECTION define plus `defines`; the G-buffer's shading point and smooth
// normal of the shadow terminator rule (gbuffer.shadow_position/shadow_normal, docs/measuring.md
// "The shading point") bound as uPosition/uGeometry (units 0, 1; xyz point and normal, w
// coverage); the shadow-space uniforms of shaders/shadow/common/shadow_space.glsl
// set, and with `depthMap` the stage's map bound as uShadowMap (unit 2). `bind` sets the
// technique's own uniforms and textures (units 3 and up).
struct ShadowScreenPass {
  std::string name;
  std::string output;        // "visibility", or "aov.<id>.<view>" for a debug view
  GLenum format = GL_R16F;   // GL_RGBA32F for debug views
  std::string fragment;
  std::vector<std::string> defines;
  bool depthMap = true;      // reads the shadow stage's "shadow.depth"
  std::vector<std::string> reads; // further frame resources (e.g. a moment table)
  std::function<void(PassBuilder&)> declare; // further declarations (e.g. a counter buffer)
  std::function<void(PassContext&, gl::Program&)> bind;
};
void addShadowScreenPass(FrameGraph& frame, const ShadowScreenPass& pass);

// Soft-shadow techniques (PCSS, VSSM, MSM) write three outputs from one shader with OUTPUT 0/1/2:
// "visibility", and the debug views "<id>.blocker_depth" and "<id>.penumbra".
std::vector<struct DebugView> softShadowDebugViews(const std::string& technique);
void addSoftShadowPasses(FrameGraph& frame, const std::string& technique, ShadowScreenPass pass);
// Their shared knobs "<id>.min_penumbra", "<id>.max_penumbra" and "<id>.max_search" (texels), and
// the uniforms uMinPenumbra/uMaxPenumbra/uMaxSearch they set (max never below min).
std::vector<ParamSpec> softShadowParams(const std::string& technique, double maxPenumbra, double penumbraUpper,
                                        double searchUpper);
void setSoftShadowUniforms(PassContext& ctx, gl::Program& program, const std::string& technique);

class ShadowFilterKit;
struct DebugView;

// The debug view "<technique>.light_depth": the stage's depth map as linear depth, 0 at the
// light's near plane and 1 at its far plane (2D maps fill the frame; cube maps are unwrapped).
DebugView lightDepthView(const std::string& technique);
void addLightDepthView(FrameGraph& frame, const std::string& view, ShadowFilterKit& kit);

class ShadowFilterKit {
public:
  static constexpr int kMaxTaps = 64;        // shaders/shadow/common/shadow_filter.glsl uTaps[64]
  static constexpr int kNoiseSize = 64;
  enum class Pattern { Grid = 0, Poisson = 1, PoissonRotated = 2 };

  // Taps in the unit disk (or square for the grid), at most kMaxTaps.
  static std::vector<glm::vec2> taps(Pattern pattern, int count);
  // Sets uTaps/uTapCount/uRotateTaps/uReceiverPlaneBias and binds the blue noise (unit 3). With
  // `linearCompare` the map (unit 2) is sampled with bilinear comparison (2x2 hardware PCF).
  void bindFilter(gl::Program& program, const std::vector<glm::vec2>& taps, bool rotate, bool receiverPlane,
                  bool linearCompare);
  // Binds the map without comparison (raw depths, for blocker searches) to `unit`.
  void bindRawDepth(PassContext& ctx, gl::Program& program, const char* uniform, int unit);
  std::size_t ownedBytes() const { return m_noise ? m_noise.desc().bytes() : 0; }

private:
  void ensure();
  gl::Texture m_noise;
  gl::Sampler m_linearCompare, m_raw;
};

} // namespace rtlab
