#version 450 core
// bloom.up<j>: u_j = a_j level_j + s tent(u_{j+1}), where u_{j+1} is the coarser result (for the
// deepest level L its own image, then s = a_L, else s = 1). The weights a_j come from the mip plan
// (techniques/bloom/bloom_model.h planMipChain) and sum to 1 with a_0, which the composite adds.
#include "filters.glsl"

uniform sampler2D uLevel;
uniform sampler2D uCoarser;
uniform float uLevelWeight;
uniform float uCoarserWeight;
uniform ivec2 uTargetSize;

layout(location = 0) out vec4 oColor;

void main() {
  vec2 uv = gl_FragCoord.xy / vec2(uTargetSize);
  vec3 level = texelFetch(uLevel, ivec2(gl_FragCoord.xy), 0).rgb;
  vec3 coarser = bloomUpsample(uCoarser, uv, 1.0 / vec2(textureSize(uCoarser, 0)));
  oColor = vec4(uLevelWeight * level + uCoarserWeight * coarser, 1.0);
}
