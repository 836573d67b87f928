#version 450 core
// Debug view of the light-space flux map: per texel Phi_p / (pi A_perp), the radiance the patch
// reflects (rho E_perp / pi, in the range of the frame's colours; Phi_p itself falls as
// 1/resolution^2). A 2D map fills the frame; a cube's faces fill a 3 x 2 atlas, +X -X +Y in the
// top row, -Y +Z -Z below. Mask 1 where light 0 sees a surface.
#include "common/rsm.glsl"
#include "../common/constants.glsl"

in vec2 vUv;
layout(location = 0) out vec4 oValue;

void main() {
  int face = 0;
  vec2 uv = vUv;
  if (uRsmProjection == kRsmCube) {
    ivec2 cell = min(ivec2(vUv * vec2(3.0, 2.0)), ivec2(2, 1));
    face = (1 - cell.y) * 3 + cell.x;
    uv = vUv * vec2(3.0, 2.0) - vec2(cell);
  }
  RsmVpl v;
  bool surface = rsmFetchUv(min(uv, vec2(1.0 - 1e-6)), face, v);
  vec2 centre = (floor(uv * float(uRsmResolution)) + 0.5) / float(uRsmResolution);
  float area = rsmPerpendicularArea(v.position, centre);
  oValue = surface ? vec4(v.flux / (kPi * area), 1.0) : vec4(0.0);
}
