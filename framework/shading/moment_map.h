// Filterable moment shadow maps for light 0 (VSSM, MSM): the scene's depth moments rendered from
// the light into "<id>.moments", then a summed-area table "<id>.sat" (RGBA32F) so a box of any
// size is averaged in four fetches. Orthographic (directional) and single perspective (spot)
// light spaces; a point light needs six maps and is refused with a usage error.
#pragma once
#include "gl/program.h"

#include <string>

namespace rtlab {

class FrameGraph;
struct PassContext;

struct MomentMapConfig {
  std::string technique;  // resource prefix
  int moments = 2;        // 2 (z, z^2) or 4 (z .. z^4)
  GLenum format = GL_RG32F;
  bool optimized = false; // 4 moments with Peters & Klein's 16-bit quantization transform
  bool satOffset = true;  // subtract 0.5 before summing (precision of the table)
};

// Adds "<id>.moments" and "<id>.sat" passes (resources of the same names).
void addMomentMapPasses(FrameGraph& frame, const MomentMapConfig& config);
// Binds "<id>.sat" as uSat (and uSatOffset) at `unit` for shaders/common/moments.glsl.
void bindMomentSat(PassContext& ctx, gl::Program& program, const MomentMapConfig& config, int unit);
std::string momentSatResource(const std::string& technique);
// Debug view "aov.<view>": the first channel of "<technique>.moments" over the frame.
void addMomentView(FrameGraph& frame, const std::string& technique, const std::string& view);

} // namespace rtlab
