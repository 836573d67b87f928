// Filterable moment shadow maps for light 0 (VSSM, MSM): the scene's depth moments rendered from
// the light into "<id>.moments", then a summed-area table "<id>.sat" (32-bit fixed point, RG32UI
// or RGBA32UI, exact box sums; 64-bit with "<id>.sat_bits" 64, the high words in a right half) so
// a box of any size is averaged in four fetches. Orthographic
// (directional) and single perspective (spot) light spaces; a point light needs six maps and is
// refused with a usage error.
#pragma once
#include "gl/program.h"
#include "params/param_spec.h"

#include <string>

namespace rtlab {

class FrameGraph;
struct PassContext;

struct MomentMapConfig {
  std::string technique;  // resource prefix
  int moments = 2;        // 2 (z, z^2) or 4 (z .. z^4)
  GLenum format = GL_RG32F;
  bool optimized = false; // 4 moments in Peters & Klein's optimized quantization basis
  bool satOffset = true;  // subtract 0.5 before summing (one more bit of fixed-point precision)
};

class ParamSet;
// "<id>.sat_bits" (32 or 64): the table's integer width (techniques/vssm/README.md, "Precision").
ParamSpec momentSatBitsParam(const std::string& technique);
// 32 or 64, from "<id>.sat_bits".
int momentSatBits(const ParamSet& params, const std::string& technique);
// Fixed-point units per moment unit of the summed-area table: the largest power of two with which
// the sum over the widest box a lookup can make (from "<id>.max_search", "<id>.min_penumbra",
// "<id>.max_penumbra" and "shadow.resolution") fits in a signed 32-bit integer (64-bit with
// "<id>.sat_bits" 64, at most 2^49: a stored float moment's fixed-point value is then exact).
float momentSatScale(const ParamSet& params, const MomentMapConfig& config);

// Adds the fragment pass "<id>.moments" (resource of the same name) and the compute passes
// "<id>.sat.rows" and "<id>.sat.columns", which build the table "<id>.sat" as a storage image.
void addMomentMapPasses(FrameGraph& frame, const MomentMapConfig& config);
// Binds "<id>.sat" as uSat (and uSatOffset, uSatScale, uSatWide) at `unit` for
// shaders/shadow/common/moments.glsl.
void bindMomentSat(PassContext& ctx, gl::Program& program, const MomentMapConfig& config, int unit);
std::string momentSatResource(const std::string& technique);
// Debug view "aov.<view>": the first channel of "<technique>.moments" over the frame.
void addMomentView(FrameGraph& frame, const std::string& technique, const std::string& view);

} // namespace rtlab
