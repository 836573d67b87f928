#version 450 core
// bloom.composite: colour = colour before bloom + intensity x bloom, clamped to 65504 (the HDR
// clamp, shaders/common/hdr.glsl); a non-finite input pixel becomes 0 as in the bright pass.
// With OUTPUT_AOV (bloom.aov) it writes intensity x bloom alone, RGBA32F with A = 1.
// The bloom at full resolution: METHOD_MIP: a_0 x the bright pass + s x tent(coarser result)
// (HAS_COARSER: the frame has at least one level); else the Gaussian octaves' sum.
#include "../common/hdr.glsl"
#include "filters.glsl"

uniform sampler2D uColor;
uniform sampler2D uBloomBase; // METHOD_MIP: bloom.bright; else bloom.sum
uniform sampler2D uCoarser;
uniform float uBaseWeight;
uniform float uCoarserWeight;
uniform float uIntensity;

layout(location = 0) out vec4 oColor;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec3 base = texelFetch(uBloomBase, px, 0).rgb;
#ifdef METHOD_MIP
  vec3 bloom = uBaseWeight * base;
#ifdef HAS_COARSER
  vec2 frame = vec2(textureSize(uBloomBase, 0));
  bloom += uCoarserWeight * bloomUpsample(uCoarser, gl_FragCoord.xy / frame, 1.0 / vec2(textureSize(uCoarser, 0)));
#endif
#else
  vec3 bloom = base;
#endif
  bloom *= uIntensity;
#ifdef OUTPUT_AOV
  oColor = vec4(bloom, 1.0);
#else
  vec4 c = texelFetch(uColor, px, 0);
  if (nonFinite(c.rgb)) c.rgb = vec3(0.0);
  oColor = vec4(clampHdr(c.rgb + bloom), c.a);
#endif
}
