#version 450 core
// Shadow mapping (Williams 1978): light 0 is visible from a surface point when the point, moved
// along its geometric normal by shadow.normal_bias texels and compared with shadow.constant_bias
// subtracted, is no farther from the light than the nearest occluder stored in the map.
#include "../shadow/common/shadow_space.glsl"

in vec2 vUv;
uniform sampler2D uPosition;
uniform sampler2D uGeometry;

layout(location = 0) out float oVisibility;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 geometry = texelFetch(uGeometry, px, 0);
  if (geometry.w < 0.5) {
    oVisibility = 0.0;
    return;
  }
  vec3 p = texelFetch(uPosition, px, 0).xyz;
  vec3 n = normalize(geometry.xyz);
  oVisibility = shadowFacesAway(p, n) ? 0.0 : shadowTestHard(shadowReceiver(p, n));
}
