// The framework's own passes: G-buffer, deferred lighting, transparent surfaces, tone mapping and
// AOV export. Techniques add theirs between them (render/renderer.cpp fixes the order).
#pragma once
#include "gl/texture.h"

#include <string>

namespace rtlab {

class FrameGraph;

// Frame-size texture descriptions.
gl::TextureDesc frameTexture(const FrameGraph& frame, GLenum format);

// Resource names of the shared inputs.
namespace res {
inline const std::string kPosition = "gbuffer.position"; // xyz world, w linear view depth
inline const std::string kNormal = "gbuffer.normal";     // xyz shading normal, w material occlusion
inline const std::string kGeometry = "gbuffer.geometry"; // xyz geometric normal, w coverage
inline const std::string kAlbedo = "gbuffer.albedo";     // rgb base color, a metallic
inline const std::string kMaterial = "gbuffer.material"; // rgb emissive, a roughness
// The shadow terminator rule (docs/measuring.md, "The shading point"): where shadow tests start.
inline const std::string kShadowPosition = "gbuffer.shadow_position"; // xyz shading point, w coverage
inline const std::string kShadowNormal = "gbuffer.shadow_normal";     // xyz smooth normal, w coverage
inline const std::string kDepth = "gbuffer.depth";
inline const std::string kColorHdr = "color.hdr";
inline const std::string kColorLdr = "color.ldr";       // tone-mapped, linear (sRGB applied on output)
} // namespace res

void addGBufferPass(FrameGraph& frame);
void addLightingPass(FrameGraph& frame);
void addTransparentPass(FrameGraph& frame); // only when the scene has transparent surfaces
void addTonemapPass(FrameGraph& frame);
// Adds the pass that writes "aov.<name>" (RGBA32F: value, mask) for a built-in AOV and returns the
// resource name. Technique debug views write "aov.<view>" themselves.
std::string addAovPass(FrameGraph& frame, const std::string& aov);
std::string aovResource(const std::string& aov);

} // namespace rtlab
