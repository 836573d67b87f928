#version 450 core
// One direction of a summed-area table (Crow 1984): each invocation scans one row (AXIS 0: from
// uInput, minus uOffset) or one column (AXIS 1: in place in the table) and writes inclusive
// prefix sums. The offset is the precision fix of Lauritzen 2007: sums of values centred on 0
// lose fewer float bits than sums of positive depths; lookups add it back.
layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2D uInput;
layout(binding = 0, rgba32f) uniform image2D uTable;
uniform int uSize;
uniform vec4 uOffset;

void main() {
  int line = int(gl_GlobalInvocationID.x);
  if (line >= uSize) return;
  vec4 sum = vec4(0.0);
  for (int i = 0; i < uSize; ++i) {
#if AXIS == 0
    ivec2 p = ivec2(i, line);
    sum += texelFetch(uInput, p, 0) - uOffset;
#else
    ivec2 p = ivec2(line, i);
    sum += imageLoad(uTable, p);
#endif
    imageStore(uTable, p, sum);
  }
}
