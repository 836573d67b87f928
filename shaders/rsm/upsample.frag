#version 450 core
// rsm.raw (indirect resolution, texel k = frame pixel k * uScale) to the frame: the stage output
// `indirect` (rgb, 0 on sky), or with OUTPUT_COUNT the rsm.vpl_count view (the raw alpha, mask
// 1 on surface). The taps are the raw texels around the pixel (base and base + 1 per axis where the
// pixel lies past its texel's own pixel), weighted bilinearly, by the distance of the pixel's point
// from each tap's tangent plane (aoPlaneWeight, shared with the ao chain's upsampling: world space
// works as well, the plane distance is rigid-invariant) and by (n . n_tap)^8; where every weight
// vanishes (a thin object none of the taps sees) the tap of nearest depth is taken. At scale 1
// it is a copy.
#include "../ao/common/bilateral.glsl"

in vec2 vUv;
uniform sampler2D uRaw;
uniform sampler2D uPosition; // gbuffer.position: xyz world, w linear depth (0 on sky)
uniform sampler2D uNormal;   // gbuffer.normal
uniform int uScale;
uniform ivec2 uRawSize;
uniform ivec2 uFullSize;

layout(location = 0) out vec4 oValue;

vec4 upsample(ivec2 px, vec3 p, float depth, vec3 n) {
  ivec2 base = px / uScale;
  if (uScale == 1) return texelFetch(uRaw, px, 0);
  vec2 frac = vec2(px - base * uScale) / float(uScale);
  vec4 sum = vec4(0.0), nearest = vec4(0.0);
  float weight = 0.0, nearestGap = 1e30;
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= 1; ++i) {
      float bilinear = (i == 0 ? 1.0 - frac.x : frac.x) * (j == 0 ? 1.0 - frac.y : frac.y);
      if (bilinear <= 0.0) continue;
      ivec2 q = min(base + ivec2(i, j), uRawSize - 1);
      ivec2 qpx = min(q * uScale, uFullSize - 1);
      vec4 qp = texelFetch(uPosition, qpx, 0);
      vec3 m = texelFetch(uNormal, qpx, 0).xyz;
      vec4 value = texelFetch(uRaw, q, 0);
      float facing = max(dot(n, m), 0.0);
      facing *= facing;
      facing *= facing;
      float w = bilinear * aoPlaneWeight(qp.xyz, m, qp.w, p) * facing * facing;
      sum += w * value;
      weight += w;
      float gap = qp.w > 0.0 ? abs(qp.w - depth) : 1e29;
      if (gap < nearestGap) {
        nearestGap = gap;
        nearest = value;
      }
    }
  return weight > 1e-4 ? sum / weight : nearest;
}

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 position = texelFetch(uPosition, px, 0);
  if (position.w <= 0.0) {
    oValue = vec4(0.0);
    return;
  }
  vec4 v = upsample(px, position.xyz, position.w, texelFetch(uNormal, px, 0).xyz);
#ifdef OUTPUT_COUNT
  oValue = vec4(vec3(v.a), 1.0);
#else
  oValue = vec4(v.rgb, 1.0);
#endif
}
