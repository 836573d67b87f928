#version 450 core
// The viewer's exposure readout (framework/viewer/window/exposure_meter.h): one invocation per 16x16
// tile of the linear colour writes its finite pixels' sum of log(delta + L), their largest L and
// their count, and its non-finite pixels' count; the CPU adds the tiles (image/exposure.h has the
// definition and the CPU version `rtlab render --stats` uses). A loop per invocation, no shared
// memory: on llvmpipe a 16x16 workgroup reducing through shared memory and barriers took as long
// as the frame itself (docs/viewer.md "Exposure readout").
#include "../common/hdr.glsl"

layout(local_size_x = 64) in;

layout(binding = 0) uniform sampler2D uColor;
layout(std430, binding = 0) writeonly buffer Tiles { vec4 tiles[]; }; // sumLog, maxL, finite, nonFinite

uniform ivec2 uSize;
uniform ivec2 uTiles; // tiles across and down

const int kTile = 16;
const float kDelta = 1e-4;

void main() {
  const int id = int(gl_GlobalInvocationID.x);
  if (id >= uTiles.x * uTiles.y) return;
  const ivec2 origin = ivec2(id % uTiles.x, id / uTiles.x) * kTile;
  const ivec2 end = min(origin + kTile, uSize);
  vec4 sum = vec4(0.0);
  for (int y = origin.y; y < end.y; ++y)
    for (int x = origin.x; x < end.x; ++x) {
      const vec3 c = texelFetch(uColor, ivec2(x, y), 0).rgb;
      if (nonFinite(c)) { // a bit test: isnan/isinf may fold away under fast math
        sum.w += 1.0;
      } else {
        const float l = max(dot(c, vec3(0.2126, 0.7152, 0.0722)), 0.0);
        sum.xyz += vec3(log(kDelta + l), 0.0, 1.0);
        sum.y = max(sum.y, l);
      }
    }
  tiles[id] = sum;
}
