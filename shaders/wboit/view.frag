#version 450 core
// wboit's debug views (RGBA32F, value in every channel, A = 1). VIEW_REVEALAGE: reveal = Π(1 - α)
// (1 where no layer covers). VIEW_WEIGHT: the accumulated weight Σ α w (the accumulation's alpha,
// unscaled). VIEW_COMPLEXITY: transparent fragments per pixel in front of the opaque depth.
uniform sampler2D uSource;
uniform float uScale; // VIEW_WEIGHT: 1 / the accumulation's scale

layout(location = 0) out vec4 oValue;

void main() {
  vec4 s = texelFetch(uSource, ivec2(gl_FragCoord.xy), 0);
#if defined(VIEW_WEIGHT)
  float v = s.a * uScale;
#else
  float v = s.r;
#endif
  oValue = vec4(vec3(v), 1.0);
}
