// The light-space G-buffer of light 0 that the indirect techniques share (rsm, lpv): a reflective
// shadow map (Dachsbacher and Stamminger 2005). Each texel is the surface patch light 0 sees
// through it, a diffuse virtual point light (VPL); techniques/rsm/README.md "The light-space
// G-buffer" derives the units. Family code (docs/architecture.md, second-wave table); shaders:
// shaders/rsm/gbuffer.frag and the include shaders/rsm/common/rsm.glsl.
//
// Layout: every map is a GL_TEXTURE_2D_ARRAY with one layer per light-space face (1 for a
// directional or narrow spot light 0, 6 for a point light or a wide spot: the faces +X -X +Y -Y
// +Z -Z of computeLightSpace), rsm resolution squared, nearest-filtered.
#pragma once
#include "techniques/common/shadow/light_space.h"

#include <string>

namespace rtlab {

class FrameGraph;
struct PassContext;
namespace gl {
class Program;
}

// RGBA32F: the reflected flux Phi_p of the texel's patch (RGB, lumen for the built-in scenes'
// photometric lights), A = 1 on surface and 0 where light 0 sees nothing. 32-bit, not 16: Phi_p
// falls as 1/resolution^2 (about 1e-5 at 1024^2 in cornell), the subnormal range of half floats.
inline const std::string kRsmFlux = "rsm.flux";
// RGBA16F: the unit world shading normal n_p, turned to face light 0; A = 1 on surface.
inline const std::string kRsmNormal = "rsm.normal";
// RGBA32F: the world position x_p; A = 1 on surface.
inline const std::string kRsmPosition = "rsm.position";
// The depth buffer of the G-buffer pass (a 2D array like the maps; DEPTH_COMPONENT32F).
inline const std::string kRsmDepth = "rsm.depth";

// The light space of the maps: light 0 with the shadow stage's projection and fit
// (computeLightSpace) at `resolution`. Error(Usage) for a rectangular light 0 (exit 2, as the
// shadow stage) and Error(Internal) for a scene without light 0.
LightSpace rsmLightSpace(const Scene& scene, int resolution);
// Adds the G-buffer passes ("rsm.gbuffer", or "rsm.gbuffer.face<N>" per cube face) once per
// frame; later calls do nothing.
void addRsmGBufferPass(FrameGraph& frame, int resolution);
// Binds the maps to units firstUnit (flux), firstUnit + 1 (normal), firstUnit + 2 (position) and
// sets the uniforms of shaders/rsm/common/rsm.glsl. The caller declares b.read() of the three maps.
void bindRsm(PassContext& ctx, gl::Program& program, int firstUnit);
// Adds the debug view `view` (aovResource(view), frame-sized RGBA32F): the flux map as the
// radiance each texel reflects, Phi_p / (pi A_perp) (shaders/rsm/flux_view.frag).
void addRsmFluxView(FrameGraph& frame, int resolution, const std::string& view);
// The resolution the G-buffer of this frame was made at (the maps' width).
int rsmResolution(const PassContext& ctx);

} // namespace rtlab
