#version 450 core
// lpv.inject / lpv.geometry: the point's SH coefficients, summed into the cell by additive
// blending (GL 4.5 has no float atomics; blending into RGBA32F is exact up to float rounding).
in flat vec4 gShR;
in flat vec4 gShG;
in flat vec4 gShB;

layout(location = 0) out vec4 oR;
#ifndef GEOMETRY_VOLUME
layout(location = 1) out vec4 oG;
layout(location = 2) out vec4 oB;
#endif

void main() {
  oR = gShR;
#ifndef GEOMETRY_VOLUME
  oG = gShG;
  oB = gShB;
#endif
}
