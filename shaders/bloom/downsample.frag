#version 450 core
// bloom.down<j>: level j-1 (the bright pass for j = 1) -> level j, half its size, through the
// 13-tap filter; uKaris on the first level only (bloom.karis).
#include "filters.glsl"

uniform sampler2D uSource;
uniform ivec2 uTargetSize;
uniform bool uKaris;

layout(location = 0) out vec4 oColor;

void main() {
  vec2 uv = gl_FragCoord.xy / vec2(uTargetSize);
  vec2 texel = 1.0 / vec2(textureSize(uSource, 0));
  oColor = vec4(bloomDownsample(uSource, uv, texel, uKaris), 1.0);
}
