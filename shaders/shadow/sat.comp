#version 450 core
// One direction of a summed-area table (Crow 1984) in fixed point: each invocation scans one row
// (AXIS 0: from uInput) or one column (AXIS 1: in place in the table) and writes inclusive prefix
// sums. Row scans first turn each moment into an integer, round((moment - uOffset) * uScale).
// Unsigned sums wrap modulo 2^32 (2^64 with WIDE), and so do the four-corner differences of a
// lookup: a box's sum comes out exact whenever it fits in the signed integer, which uScale
// guarantees for every box a lookup makes (momentSatScale, techniques/common/shadow/moment_map.cpp).
// A float table instead rounds its running sums, whose size grows with the map, and a small box's
// mean then loses its low digits (techniques/vssm/README.md, "Speckles"). FORMAT is the image
// format (rg32ui or rgba32ui). Each direction is one compute pass of the frame graph, which binds
// the table to image unit 0 and issues the barriers between them.
//
// WIDE (`<id>.sat_bits` 64; techniques/vssm/README.md, "Precision"): 64-bit sums, the low words in
// the left half of a table twice as wide as the map, the high words in the right half. uScale is
// then up to 2^49, so a texel's fixed-point value is its stored float moment exactly: v =
// round((m - offset) * uScale) has at most 24 significant bits, and its split into
// hi = floor(v / 2^32) and lo = v - hi * 2^32 is exact in float.
layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2D uInput;
layout(binding = 0, FORMAT) uniform uimage2D uTable;
uniform int uSize;
uniform vec4 uOffset;
uniform float uScale;

void main() {
  int line = int(gl_GlobalInvocationID.x);
  if (line >= uSize) return;
  uvec4 sum = uvec4(0u);
#ifdef WIDE
  uvec4 high = uvec4(0u);
  const ivec2 toHigh = ivec2(uSize, 0);
#endif
  for (int i = 0; i < uSize; ++i) {
#if AXIS == 0
    ivec2 p = ivec2(i, line);
    vec4 v = round((texelFetch(uInput, p, 0) - uOffset) * uScale);
#ifdef WIDE
    vec4 hi = floor(v * (1.0 / 4294967296.0));
    uvec4 carry;
    sum = uaddCarry(sum, uvec4(v - hi * 4294967296.0), carry);
    high += uvec4(ivec4(hi)) + carry;
#else
    sum += uvec4(ivec4(v));
#endif
#else
    ivec2 p = ivec2(line, i);
#ifdef WIDE
    uvec4 carry;
    sum = uaddCarry(sum, imageLoad(uTable, p), carry);
    high += imageLoad(uTable, p + toHigh) + carry;
#else
    sum += imageLoad(uTable, p);
#endif
#endif
    imageStore(uTable, p, sum);
#ifdef WIDE
    imageStore(uTable, p + toHigh, high);
#endif
  }
}
