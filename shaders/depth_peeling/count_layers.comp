#version 450 core
// depth_peeling.count<k> (the debug view depth_peeling.layers): adds 1 where layer k peeled a
// fragment, i.e. where its depth target (which starts as the opaque depth and is lowered only by a
// fragment passing GL_LESS) ends in front of the opaque depth. uFirst: layer 0 starts the count.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D uLayerDepth;
layout(binding = 1) uniform sampler2D uOpaqueDepth;
layout(binding = 0, rgba32f) uniform image2D uCount;
uniform bool uFirst;
uniform ivec2 uSize;

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(px, uSize))) return;
  float count = uFirst ? 0.0 : imageLoad(uCount, px).r;
  if (texelFetch(uLayerDepth, px, 0).r < texelFetch(uOpaqueDepth, px, 0).r) count += 1.0;
  imageStore(uCount, px, vec4(vec3(count), 1.0));
}
