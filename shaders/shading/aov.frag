#version 450 core
// Writes one AOV as RGBA32F: rgb the value (docs/contract.md "Images and AOVs"), a the surface mask.
// Background pixels hold 0 in every data AOV. AOV_* selects which one (set as a define);
// AOV_COVERAGE_ALPHA takes the mask from the source's alpha (> 0: covered) instead of the G-buffer,
// so transparent layers over the background count (AOV transparency, docs/stages.md "Stage AOVs").
in vec2 vUv;
uniform sampler2D uPosition;
uniform sampler2D uNormal;
uniform sampler2D uGeometry;
uniform sampler2D uAlbedo;
uniform sampler2D uSource;   // the stage output or color, when the AOV has one
uniform bool uHasSource;
uniform float uDefault;      // value of a stage AOV when no technique of the stage is active

layout(location = 0) out vec4 oValue;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
#if defined(AOV_COVERAGE_ALPHA)
  float mask = texelFetch(uSource, px, 0).a > 0.0 ? 1.0 : 0.0;
#else
  float mask = texelFetch(uGeometry, px, 0).w >= 0.5 ? 1.0 : 0.0;
#endif
  vec3 value = vec3(0.0);
#if defined(AOV_DEPTH)
  value = vec3(texelFetch(uPosition, px, 0).w);
#elif defined(AOV_NORMAL)
  vec3 n = texelFetch(uNormal, px, 0).xyz;
  value = dot(n, n) > 0.0 ? normalize(n) : vec3(0.0);
#elif defined(AOV_ALBEDO)
  value = texelFetch(uAlbedo, px, 0).rgb;
#elif defined(AOV_COLOR)
  // color keeps the background color (it is an image, not data).
  oValue = vec4(texelFetch(uSource, px, 0).rgb, mask);
  return;
#else
  value = uHasSource ? texelFetch(uSource, px, 0).rgb : vec3(uDefault);
#endif
  oValue = vec4(value * mask, mask);
}
