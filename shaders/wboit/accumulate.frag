#version 450 core
// wboit.accumulate: every transparent fragment in front of the opaque depth (test on, no write),
// in any order. Target 0 (accumulation, blend ONE, ONE): (α C w, α w) * uAccumScale, the sums of
// the contract; target 1 (revealage, cleared to 1, blend ZERO, ONE_MINUS_SRC_COLOR): α in every
// channel, so each fragment multiplies it by 1 - α. techniques/wboit/README.md "Numerical guards"
// explains uAccumScale and uFragmentCap.
in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vTangent;
in vec2 vUv;

#include "../shading/layer.glsl"
#include "weight.glsl"

uniform mat4 uView;
uniform float uAccumScale;  // sigma: 1/16 for an RGBA16F accumulation, 1 for RGBA32F
uniform float uFragmentCap; // the largest value one fragment may add to a channel

#ifdef WBOIT_COUNT
// [0]: fragments whose share was capped (on the frames that stats count).
layout(std430, binding = 0) buffer WboitCounts {
  uint uWboitCounts[];
};
#endif

layout(location = 0) out vec4 oAccum;
layout(location = 1) out vec4 oReveal;

void main() {
  LayerFragment f = shadeLayer();
  float viewZ = (uView * vec4(vWorldPos, 1.0)).z;
  float w = wboitWeight(f.radiance, f.alpha, viewZ, gl_FragCoord.z);
  vec4 accum = vec4(f.radiance * f.alpha, f.alpha) * (w * uAccumScale);
  // An HDR fragment whose (α C w) would not fit: its weight is lowered so that its largest channel
  // is the cap; its colour in the average is kept.
  float peak = max(max(accum.r, accum.g), max(accum.b, accum.a));
  if (peak > uFragmentCap) {
    accum *= uFragmentCap / peak;
#ifdef WBOIT_COUNT
    atomicAdd(uWboitCounts[0], 1u);
#endif
  }
  oAccum = accum;
  oReveal = vec4(f.alpha);
}
