// The shadow stage's light-space depth map of light 0 (owned by the stage, shared by every
// depth-comparison technique: docs/architecture.md "Stages and slots"). Resource "shadow.depth":
// a 2D depth texture, or a cube map for point lights and wide spots, with hardware depth
// comparison enabled.
#pragma once
#include "techniques/common/shadow/light_space.h"

#include <string>

namespace rtlab {

class FrameGraph;
class ParamSet;
struct PassContext;
namespace gl { class Program; }

inline const std::string kShadowDepth = "shadow.depth";

// The light space every shadow technique uses this frame (shadow.* params, light 0, bounds).
LightSpace shadowLightSpace(const Scene& scene, const ParamSet& params);
// Adds the "shadow.depth" pass (once per frame; later calls do nothing).
void addShadowDepthPass(FrameGraph& frame);
// Sets the uniforms of shaders/shadow/common/shadow_space.glsl (light 0's size too) and binds the map
// to `unit` (none when unit < 0).
void bindShadowSpace(PassContext& ctx, gl::Program& program, int unit);
// "SHADOW_PROJECTION <n>" define for shadow_space.glsl.
std::string shadowProjectionDefine(const LightSpace& ls);

} // namespace rtlab
