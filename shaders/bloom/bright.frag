#version 450 core
// bloom.bright: the colour before bloom -> the bright pass in the storage format (bloom.format).
// A pixel with a NaN or infinite channel (from an earlier pass) becomes 0 so that the blur cannot
// spread it; channels above the storage format's largest value are clamped to it. With BLOOM_COUNT
// (a frame whose stats are written) both are counted, once per pixel, in the buffer at binding 0
// (techniques/bloom/bloom.cpp kCountsBinding): [0] non-finite pixels, [1] clamped pixels.
#include "../common/hdr.glsl"
#include "bright.glsl"

uniform sampler2D uColor;
uniform vec3 uStorageMax;

#ifdef BLOOM_COUNT
layout(std430, binding = 0) buffer BloomCounts {
  uint uNonFinite;
  uint uClamped;
};
#endif

layout(location = 0) out vec4 oBright;

void main() {
  vec3 c = texelFetch(uColor, ivec2(gl_FragCoord.xy), 0).rgb;
  if (nonFinite(c)) {
#ifdef BLOOM_COUNT
    atomicAdd(uNonFinite, 1u);
#endif
    c = vec3(0.0);
  }
  if (any(greaterThan(c, uStorageMax))) {
#ifdef BLOOM_COUNT
    atomicAdd(uClamped, 1u);
#endif
    c = min(c, uStorageMax);
  }
  oBright = vec4(c * bloomBrightWeight(c), 1.0);
}
