// The framework's own passes: G-buffer, deferred lighting, transparent surfaces, tone mapping and
// AOV export. Techniques add theirs between them, in the order of the stage table (frame/stages.h,
// docs/stages.md); the renderer names the colour resource each pass reads and writes.
#pragma once
#include "gl/texture.h"

#include <string>

namespace rtlab {

class FrameGraph;
struct PassContext;
namespace gl { class Program; }

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
inline const std::string kColorHdr = "color.hdr"; // the final colour when a pass writes it (see colorResource)
inline const std::string kColorLdr = "color.ldr";       // tone-mapped, linear (sRGB applied on output)
} // namespace res

// The resource that holds colour version `version` ("lit" -> "color.lit") when a pass writes it;
// a version no pass changes is an alias of the one before (Renderer::colorResource resolves it).
std::string colorResource(const std::string& version);

void addGBufferPass(FrameGraph& frame);
// Deferred lighting into `output` (RGBA16F). Reads the outputs of the stages that feed it, as their
// declared LightingEffect says. rectLightsAsPoints false: an arealight technique is active and adds
// the rectangular lights itself, so they are skipped here.
void addLightingPass(FrameGraph& frame, const std::string& output, bool rectLightsAsPoints);
// The built-in pass a stage declares as its fallback (StageInfo::fallback), from colour `input` to
// `output`. Error(Internal) for an unknown fallback name.
void addStageFallback(FrameGraph& frame, const std::string& fallback, const std::string& input, const std::string& output);
// Transparent surfaces over `input`, written to `output` (the stage's fallback "transparent").
void addTransparentPass(FrameGraph& frame, const std::string& input, const std::string& output);
// The uniforms of a program that draws the transparent layers with shading/surface.vert and
// shading/layer.glsl: uViewProj, uCameraPosition, uAmbient and the lights. Every pass that shades
// layer fragments sets them through here (the fallback, the transparency techniques, the capture).
void setLayerUniforms(gl::Program& program, const PassContext& ctx);
void addTonemapPass(FrameGraph& frame, const std::string& color);
// Where a built-in AOV's value comes from in this frame: the renderer resolves it from the stage
// table (StageInfo::aov, docs/stages.md "Stage AOVs").
struct AovSource {
  std::string resource;       // copied when it exists; empty: `neutral`
  bool required = false;      // the resource must have been written (a read, not readIfPresent)
  float neutral = 0.0f;       // the value on surface pixels where the resource is absent
  bool colorImage = false;    // an image (color, transparency): the background keeps its colour
  bool coverageAlpha = false; // A = 1 where the resource's alpha is above 0, not the G-buffer's mask
};
// Adds the pass that writes "aov.<name>" (RGBA32F: value, mask) for a built-in AOV and returns the
// resource name; depth, normal and albedo come from the G-buffer, the others from `source`.
// Technique debug views write "aov.<view>" themselves.
std::string addAovPass(FrameGraph& frame, const std::string& aov, const AovSource& source);
std::string aovResource(const std::string& aov);

} // namespace rtlab
