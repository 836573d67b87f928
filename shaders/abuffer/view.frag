#version 450 core
// abuffer's debug views (RGBA32F, A = 1) from the list lengths the resolve stored: VIEW_COMPLEXITY
// the fragments per pixel (the depth complexity of the transparent layers in front of the opaque
// surface); VIEW_DROPPED the fragments the resolve dropped there, max(0, length - MAX_FRAGMENTS).
#ifndef MAX_FRAGMENTS
#define MAX_FRAGMENTS 32
#endif

uniform usampler2D uCounts;

layout(location = 0) out vec4 oValue;

void main() {
  uint n = texelFetch(uCounts, ivec2(gl_FragCoord.xy), 0).r;
#ifdef VIEW_DROPPED
  n = n > uint(MAX_FRAGMENTS) ? n - uint(MAX_FRAGMENTS) : 0u;
#endif
  oValue = vec4(vec3(float(n)), 1.0);
}
