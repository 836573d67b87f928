// Light propagation volumes (techniques/lpv/README.md): the 2-band real SH basis, the clamped
// cosine lobe, and the grid's placement. The CPU model in techniques/lpv/lpv_model.cpp has the
// same functions.
//
// Coefficient order (Y00, Y1-1, Y10, Y11), i.e. (constant, y, z, x). Every volume holds one
// RGBA texel of these four coefficients per cell and colour channel.
const float kShY00 = 0.28209479177; // 1 / (2 sqrt(pi))
const float kShY1 = 0.48860251190;  // sqrt(3 / (4 pi))
// max(0, n.w) in SH: sqrt(pi)/2 for Y00 and sqrt(pi/3) n for band 1.
const float kLobeC0 = 0.88622692545; // sqrt(pi) / 2
const float kLobeC1 = 1.02332670795; // sqrt(pi / 3)

uniform vec3 uGridOrigin; // world position of the grid's corner (cell (0,0,0)'s minimum)
uniform float uCellSize;  // world size of one cubic cell
uniform int uGridSize;    // cells per axis
uniform int uShBands;     // 1 or 2

vec4 shBasis(vec3 w) { return vec4(kShY00, kShY1 * w.y, kShY1 * w.z, kShY1 * w.x); }

// The lobe max(0, n.w); band 1 dropped for uShBands = 1.
vec4 shCosineLobe(vec3 n) {
  float c1 = uShBands >= 2 ? kLobeC1 : 0.0;
  return vec4(kLobeC0, c1 * n.y, c1 * n.z, c1 * n.x);
}

float shEval(vec4 c, vec3 w) { return dot(c, shBasis(w)); }

// Flux of an intensity distribution: its integral over the sphere, 4 pi Y00 c00.
float shFlux(vec4 c) { return 4.0 * 3.14159265358979 * kShY00 * c.x; }

// Grid coordinates (in cells, continuous) of world point p.
vec3 lpvCellCoord(vec3 p) { return (p - uGridOrigin) / uCellSize; }
