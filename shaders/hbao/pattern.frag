#version 450 core
// Sample-pattern view: probe pixels on a grid of uProbeSpacing pixels, each with the taps of
// its march drawn in colour over the raw AO (dimmed grey): red taps raised the horizon (they
// occlude), green taps lay within ao.radius below the horizon, blue taps were skipped
// (off-screen, background or farther than ao.radius); the probe itself is white. A pixel looks
// at the probes of the 5x5 cells around it, so taps up to two cells from their probe show.
#include "march.glsl"

uniform int uProbeSpacing;

layout(location = 0) out vec4 oView;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  Center c;
  bool surface = loadCenter(px, c);
  vec3 color = surface ? vec3(0.35 * ambientOcclusion(c, pixelJitter(px))) : vec3(0.0);
  ivec2 cell = px / uProbeSpacing;
  int best = kTapNone;
  for (int cy = -2; cy <= 2; ++cy) {
    for (int cx = -2; cx <= 2; ++cx) {
      ivec2 probe = (cell + ivec2(cx, cy)) * uProbeSpacing + uProbeSpacing / 2;
      if (any(lessThan(probe, ivec2(0))) || any(greaterThanEqual(probe, uGbufferSize))) continue;
      Center pc;
      if (!loadCenter(probe, pc)) continue;
      if (probe == px) best = 4;
      vec2 jitter = pixelJitter(probe);
      for (int k = 0; k < uDirections; ++k) best = max(best, marchDirection(pc, directionOf(k, jitter.x), jitter.y, px).watched);
    }
  }
  vec3 colors[5] = vec3[5](color, vec3(0.1, 0.3, 1.0), vec3(0.1, 0.9, 0.2), vec3(1.0, 0.15, 0.1), vec3(1.0));
  oView = vec4(colors[best], surface || best != kTapNone ? 1.0 : 0.0);
}
