#version 450 core
// depth_peeling.composite: the colour output = Over of the peeled layers onto what lies behind
// them (under.glsl resolveOver), clamped to 65504 (shaders/common/hdr.glsl). Behind them: the
// opaque colour, or with TAIL_BLEND the tail's order-independent estimate in front of it,
//   tail = (1 - P) * S / A + P * C_opaque,  S = sum a_i C_i, A = sum a_i, P = prod (1 - a_i)
// over the fragments behind the last layer (exact for one such fragment; approximate for more:
// techniques/depth_peeling/README.md "Tail"). Alpha: the coverage 1 - T * P * (1 - opaque alpha).
#include "../common/hdr.glsl"
#include "under.glsl"

uniform sampler2D uColor;
uniform sampler2D uAccum;
#ifdef TAIL_BLEND
uniform sampler2D uTailSum;
uniform sampler2D uTailReveal;
#endif

layout(location = 0) out vec4 oColor;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 opaque = texelFetch(uColor, px, 0);
  vec4 acc = texelFetch(uAccum, px, 0);
  vec3 behind = opaque.rgb;
  float reveal = 1.0;
#ifdef TAIL_BLEND
  vec4 sum = texelFetch(uTailSum, px, 0);
  reveal = texelFetch(uTailReveal, px, 0).r;
  // A = 0: no tail fragment with coverage (then P = 1 too), nothing to average.
  vec3 average = sum.a > 0.0 ? sum.rgb / sum.a : vec3(0.0);
  behind = (1.0 - reveal) * average + reveal * opaque.rgb;
#endif
  oColor = vec4(clampHdr(resolveOver(acc, behind)), 1.0 - acc.a * reveal * (1.0 - opaque.a));
}
