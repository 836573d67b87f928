#version 450
// Unfolds a 3D texture into a 2D target: pixel (x, y) shows voxel (x % n, y, x / n) (tests/render/test_frame_graph.cpp).
uniform sampler3D uVolume;
uniform int uSize;
out vec4 fragColor;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  fragColor = texelFetch(uVolume, ivec3(p.x % uSize, p.y, p.x / uSize), 0);
}
