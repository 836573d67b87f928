#version 450 core
// depth_peeling.under<k>: composites layer k (depth_peeling.layer, premultiplied (a*C, a)) under
// the layers before it in the accumulation (C, T) (under.glsl). Each invocation reads and writes
// its own pixel only, so the image load and store need no synchronisation within the pass; the
// frame graph issues the barrier between passes. uFirst: layer 0, the accumulation starts at
// (0, 0, 0, 1) rather than being read.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D uLayer;
layout(binding = 0, rgba32f) uniform image2D uAccum;
uniform bool uFirst;
uniform ivec2 uSize;

#include "under.glsl"

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(px, uSize))) return;
  vec4 acc = uFirst ? vec4(0.0, 0.0, 0.0, 1.0) : imageLoad(uAccum, px);
  imageStore(uAccum, px, compositeUnder(acc, texelFetch(uLayer, px, 0)));
}
