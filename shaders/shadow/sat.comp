#version 450 core
// One direction of a summed-area table (Crow 1984) in 32-bit fixed point: each invocation scans
// one row (AXIS 0: from uInput) or one column (AXIS 1: in place in the table) and writes
// inclusive prefix sums. Row scans first turn each moment into an integer,
// round((moment - uOffset) * uScale). Unsigned sums wrap modulo 2^32, and so do the four-corner
// differences of a lookup: a box's sum comes out exact whenever it fits in a signed 32-bit
// integer, which uScale guarantees for every box a lookup makes (momentSatScale,
// techniques/common/shadow/moment_map.cpp). A float table instead rounds its running sums, whose size
// grows with the map, and a small box's mean then loses its low digits (techniques/vssm/README.md,
// "Speckles"). FORMAT is the image format (rg32ui or rgba32ui). Each direction is one compute pass of
// the frame graph, which binds the table to image unit 0 and issues the barriers between them.
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
  for (int i = 0; i < uSize; ++i) {
#if AXIS == 0
    ivec2 p = ivec2(i, line);
    sum += uvec4(ivec4(round((texelFetch(uInput, p, 0) - uOffset) * uScale)));
#else
    ivec2 p = ivec2(line, i);
    sum += imageLoad(uTable, p);
#endif
    imageStore(uTable, p, sum);
  }
}
