#version 450 core
// wboit.composite: the transparent layers' weighted average over the opaque colour (docs/
// contract.md "Transparency"): R = (1 - reveal) * accum.rgb / clamp(accum.a, 1e-4, 5e4) +
// reveal * C_opaque, clamped to 65504 (the HDR clamp). A = 1 - reveal * (1 - A_opaque), the
// coverage of the layers over the opaque colour.
#include "../common/hdr.glsl"

uniform sampler2D uColor;  // the opaque colour (the stage's input)
uniform sampler2D uAccum;  // the accumulation, scaled by uAccumScale
uniform sampler2D uReveal; // Π(1 - α)
uniform float uAccumScale;
uniform float uStorageMax; // the accumulation format's largest finite value

layout(location = 0) out vec4 oColor;

#ifdef WBOIT_COUNT
// [1]: pixels where a sum reached the format's largest value: +inf on hardware, 65504 where the
// conversion saturates (llvmpipe) (on the frames that stats count).
layout(std430, binding = 0) buffer WboitCounts {
  uint uWboitCounts[];
};
#endif

// The composite of the contract from the sums accum = Σ (α C w, α w) and reveal = Π(1 - α).
vec3 wboitComposite(vec4 accum, float reveal, vec3 opaque) {
  // exercise(wboit-composite): begin
  // task: The composite. The weighted average of the layers' colours is accum.rgb / accum.a, with
  // task: the divisor clamped to [1e-4, 5e4] (where no layer covers, accum = 0 and the average is 0).
  // task: The layers cover 1 - reveal of the pixel and the opaque colour shows through the rest:
  // task: return (1 - reveal) * average + reveal * opaque. With every α = 0 this must be opaque
  // task: exactly.
  vec3 average = accum.rgb / clamp(accum.a, 1e-4, 5e4);
  return (1.0 - reveal) * average + reveal * opaque;
  // exercise: stub
  // return opaque; // no layer at all
  // exercise: end
}

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 opaque = texelFetch(uColor, px, 0);
  // A sum that overflowed the format (more capped fragments than the guard allows) is read as the
  // format's largest value, so the result stays finite (wrong there, and counted).
  vec4 stored = texelFetch(uAccum, px, 0);
#ifdef WBOIT_COUNT
  if (any(greaterThanEqual(stored, vec4(uStorageMax)))) atomicAdd(uWboitCounts[1], 1u);
#endif
  vec4 accum = min(stored, vec4(uStorageMax)) / uAccumScale;
  float reveal = clamp(texelFetch(uReveal, px, 0).r, 0.0, 1.0);
  oColor = vec4(clampHdr(wboitComposite(accum, reveal, opaque.rgb)), 1.0 - reveal * (1.0 - opaque.a));
}
