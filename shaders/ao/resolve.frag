#version 450 core
// The ao stage output at frame resolution: the AO-resolution result copied (full resolution) or
// upsampled (half): the 2x2 AO texels around the pixel, weighted bilinearly and by the bilateral
// weight against the pixel's own surface, falling back to the texel of nearest depth where every
// weight vanishes (a thin object seen by none of them). NEAREST takes the covering texel (the raw
// debug view). Sky pixels get 0 (and mask 0 with OUTPUT_AOV, which writes RGBA32F value + mask):
// they are told by their linear depth, which the G-buffer clears to 0 and every surface writes
// as at least the near distance (one fetch fewer per pixel than reading gbuffer.geometry's
// coverage: the pass runs at frame resolution and costs the most of the half-resolution chain).
#include "common/ao_common.glsl"
#include "common/bilateral.glsl"

in vec2 vUv;
uniform sampler2D uSource;   // AO resolution
uniform sampler2D uPosition; // gbuffer.position (w linear depth, 0 on sky)
uniform sampler2D uNormal;   // gbuffer.normal
uniform mat4 uView;

#ifdef OUTPUT_AOV
layout(location = 0) out vec4 oValue;
#else
layout(location = 0) out float oAo;
#endif

// `depth`: the pixel's linear depth (> 0).
float resolveAo(ivec2 px, float depth) {
  ivec2 base = px / uScale;
#ifdef NEAREST
  return texelFetch(uSource, min(base, uAoSize - 1), 0).r;
#else
  if (uScale == 1) return texelFetch(uSource, px, 0).r;
  vec3 p = aoViewPosition(vec2(px) + 0.5, depth);
  vec3 n = aoViewNormal(uView, texelFetch(uNormal, px, 0).xyz);
  ivec2 odd = px - base * uScale; // 0 on the texel's own pixel, 1 half-way to the next
  float sum = 0.0, weight = 0.0, nearest = 1.0, nearestGap = 1e30;
  for (int j = 0; j <= odd.y; ++j)
    for (int i = 0; i <= odd.x; ++i) {
      ivec2 q = min(base + ivec2(i, j), uAoSize - 1);
      vec4 v = texelFetch(uAoView, q, 0);
      float value = texelFetch(uSource, q, 0).r;
      float w = aoBilateralWeight(p, n, aoTexelPosition(q, v.w), v.xyz, v.w);
      sum += w * value;
      weight += w;
      float gap = v.w > 0.0 ? abs(v.w - depth) : 1e29;
      if (gap < nearestGap) {
        nearestGap = gap;
        nearest = value;
      }
    }
  return weight > 1e-4 ? sum / weight : nearest;
#endif
}

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(uPosition, px, 0).w;
  bool surface = depth > 0.0;
  float ao = surface ? resolveAo(px, depth) : 0.0;
#ifdef OUTPUT_AOV
  oValue = vec4(vec3(ao), surface ? 1.0 : 0.0);
#else
  oAo = ao;
#endif
}
