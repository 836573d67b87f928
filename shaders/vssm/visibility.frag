#version 450 core
// Variance soft shadow mapping (Yang et al. 2010) on variance shadow maps (Donnelly & Lauritzen
// 2006). Moments (z, z^2) of normalized linear light depth, averaged over any box in O(1) from a
// summed-area table. 1. Blocker search: over the region the light subtends, Chebyshev's bound
// P = sigma^2 / (sigma^2 + (t - mu)^2) estimates the unoccluded fraction; with unoccluded depth
// assumed at t, the blocker depth is z_occ = (mu - P t) / (1 - P). 2. Penumbra from similar
// triangles (as PCSS). 3. Visibility = Chebyshev bound over the penumbra box, with light-bleeding
// reduction. OUTPUT: 0 visibility, 1 blocker depth (0 = none), 2 filter radius / max penumbra.
#include "../shadow/common/shadow_space.glsl"
#include "../shadow/common/moments.glsl"

in vec2 vUv;
uniform sampler2D uPosition;
uniform sampler2D uGeometry;
uniform float uMinVariance;
uniform float uBleedReduction;
uniform float uMinPenumbra;
uniform float uMaxPenumbra;
uniform float uMaxSearch;

layout(location = 0) out vec4 oValue;

float linearFromNormalized(float z) { return uLightNear + z * (uLightFar - uLightNear); }

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 geometry = texelFetch(uGeometry, px, 0);
  float mask = geometry.w < 0.5 ? 0.0 : 1.0;
  vec3 q = shadowReceiver(texelFetch(uPosition, px, 0).xyz, mask > 0.0 ? normalize(geometry.xyz) : vec3(0.0));
  vec3 coord;
  bool inside = shadowCoord2D(q, coord);
  float zR = dot(q - uLightPosition, uLightDirection);  // linear depth along the light's axis
  float t = (zR - uLightNear) / (uLightFar - uLightNear) - uConstantBias;

  float visibility = 1.0, blockerShown = 0.0, radius = 0.0;
  vec3 n = mask > 0.0 ? normalize(geometry.xyz) : vec3(0.0);
  if (mask > 0.0 && shadowFacesAway(texelFetch(uPosition, px, 0).xyz, n)) {
    visibility = 0.0;
  } else if (inside && mask > 0.0) {
    float search = clamp(shadowSearchTexels(zR), 1.0, uMaxSearch);
    float zOcc;
    if (momentBlockerDepth(boxMoments(coord.xy, search).xy, t, uMinVariance, zOcc)) {
      float zB = linearFromNormalized(zOcc);
      radius = clamp(shadowPenumbraTexels(zR, zB), uMinPenumbra, uMaxPenumbra);
      vec2 f = boxMoments(coord.xy, radius).xy;
      visibility = reduceBleeding(chebyshevUpperBound(f, t, uMinVariance), uBleedReduction);
      blockerShown = zOcc;
    }
  }
#if OUTPUT == 1
  oValue = vec4(vec3(blockerShown * mask), mask);
#elif OUTPUT == 2
  oValue = vec4(vec3(radius / max(uMaxPenumbra, 1e-6) * mask), mask);
#else
  oValue = vec4(visibility * mask);
#endif
}
