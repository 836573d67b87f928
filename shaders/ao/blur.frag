#version 450 core
// One direction of the separable bilateral blur of the AO (Gaussian in pixels, sigma = radius/2,
// times the plane/normal weight of bilateral.glsl), at the AO resolution.
#include "common/ao_common.glsl"
#include "common/bilateral.glsl"

in vec2 vUv;
uniform sampler2D uSource;
uniform ivec2 uDirection;
uniform int uBlurRadius; // AO texels, >= 1

layout(location = 0) out float oAo;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  AoSurface c;
  float centre = texelFetch(uSource, px, 0).r;
  if (!aoSurface(px, c)) {
    oAo = centre;
    return;
  }
  float sigma = 0.5 * float(uBlurRadius);
  float sum = centre, weight = 1.0;
  for (int i = -uBlurRadius; i <= uBlurRadius; ++i) {
    if (i == 0) continue;
    ivec2 q = px + i * uDirection;
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, uAoSize))) continue;
    vec4 v = texelFetch(uAoView, q, 0);
    float w = exp(-0.5 * float(i * i) / (sigma * sigma)) *
              aoBilateralWeight(c.p, c.n, aoTexelPosition(q, v.w), v.xyz, v.w);
    sum += w * texelFetch(uSource, q, 0).r;
    weight += w;
  }
  oAo = sum / weight;
}
