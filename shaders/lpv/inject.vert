#version 450 core
// lpv.inject and lpv.geometry (techniques/lpv/README.md "Injection"): one point per texel of the
// light-space G-buffer (rsm.*), drawn without vertex buffers. The texel's VPL goes to the cell
// containing x_p + offset * cell * n_p (light volume), or its surfel to the geometry volume's
// cell (cell corners: cell k's centre is the light volume's corner k). Empty texels are dropped
// (a point outside the clip volume).
#include "../rsm/common/rsm.glsl"
#include "sh.glsl"

uniform float uInjectionOffset; // in cells, along n_p (light volume only)
uniform int uTargetSize;        // cells per axis of the target volume (N, or N + 1 for geometry)

out VertexData {
  flat vec4 shR;
  flat vec4 shG;
  flat vec4 shB;
  flat int layer;
} vOut;

void main() {
  int perFace = uRsmResolution * uRsmResolution;
  int face = gl_VertexID / perFace;
  int index = gl_VertexID - face * perFace;
  ivec2 texel = ivec2(index % uRsmResolution, index / uRsmResolution);
  RsmVpl v;
  gl_PointSize = 1.0;
  gl_Position = vec4(2.0, 2.0, 2.0, 1.0); // outside: dropped
  vOut.layer = 0;
  vOut.shR = vOut.shG = vOut.shB = vec4(0.0);
  if (!rsmFetch(texel, face, v)) return;
  vec3 n = normalize(v.normal);
#ifdef GEOMETRY_VOLUME
  // Blocking probability of the surfel in its cell: V(w) = A_s / s^2 max(0, n_s.w), A_s the
  // patch's area A_perp / cos (cos clamped at kMinCos so a grazing texel cannot claim an unbounded
  // area; V is clamped to [0, 1] where it is read).
  const float kMinCos = 0.25;
  vec2 uv = (vec2(texel) + 0.5) / float(uRsmResolution);
  vec3 toLight = uRsmProjection == kRsmOrthographic ? -uRsmLightDirection : normalize(uRsmLightPosition - v.position);
  float area = rsmPerpendicularArea(v.position, uv) / max(dot(n, toLight), kMinCos);
  vec4 lobe = min(area / (uCellSize * uCellSize), 1.0) * shCosineLobe(n);
  vec3 cell = floor(lpvCellCoord(v.position) + 0.5);
  vOut.shR = lobe;
#else
  // The VPL's intensity I_p(w) = (Phi_p / pi) max(0, n_p.w).
  vec4 lobe = shCosineLobe(n) / 3.14159265358979;
  vec3 cell = floor(lpvCellCoord(v.position + uInjectionOffset * uCellSize * n));
  vOut.shR = v.flux.r * lobe;
  vOut.shG = v.flux.g * lobe;
  vOut.shB = v.flux.b * lobe;
#endif
  if (any(lessThan(cell, vec3(0.0))) || any(greaterThanEqual(cell, vec3(uTargetSize)))) return;
  vOut.layer = int(cell.z);
  gl_Position = vec4((cell.xy + 0.5) / float(uTargetSize) * 2.0 - 1.0, 0.0, 1.0);
}
