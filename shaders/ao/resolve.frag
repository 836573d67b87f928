#version 450 core
// The ao stage output at frame resolution: the AO-resolution result copied (full resolution) or
// upsampled (half): the 2x2 AO texels around the pixel, weighted bilinearly and by the distance
// of the pixel's point from each texel's tangent plane (aoPlaneWeight in bilateral.glsl), falling
// back to the texel of nearest depth where every weight vanishes (a thin object seen by none of
// them). NEAREST takes the covering texel (the raw debug view). Sky pixels get 0 (and mask 0 with
// OUTPUT_AOV, which writes RGBA32F value + mask). The pass runs at frame resolution, the costliest
// of the half-resolution chain, so it reads one G-buffer texel per pixel: the linear depth, which
// is 0 exactly on sky pixels (cleared to 0; every surface lies at least the near distance away).
#include "common/ao_common.glsl"
#include "common/bilateral.glsl"

in vec2 vUv;
uniform sampler2D uSource;   // AO resolution
uniform sampler2D uPosition; // gbuffer.position (w linear depth, 0 on sky)

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
  ivec2 odd = px - base * uScale; // 0 on the texel's own pixel, 1 half-way to the next
  float sum = 0.0, weight = 0.0, nearest = 1.0, nearestGap = 1e30;
  for (int j = 0; j <= odd.y; ++j)
    for (int i = 0; i <= odd.x; ++i) {
      ivec2 q = min(base + ivec2(i, j), uAoSize - 1);
      vec4 v = texelFetch(uAoView, q, 0);
      float value = texelFetch(uSource, q, 0).r;
      float w = aoPlaneWeight(aoTexelPosition(q, v.w), v.xyz, v.w, p);
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
