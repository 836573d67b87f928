#version 450
// The compute example of docs/adding-a-technique.md as a test: writes the ao stage output as a
// storage image, 0.25 on surface pixels and 0 on background (tests/render/test_compute_technique.cpp).
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, r16f) writeonly uniform image2D uAo;
layout(binding = 0) uniform sampler2D uGeometry;

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(px, imageSize(uAo)))) return;
  float coverage = texelFetch(uGeometry, px, 0).w;
  imageStore(uAo, px, vec4(coverage >= 0.5 ? 0.25 : 0.0));
}
