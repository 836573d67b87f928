#version 450 core
// Moment shadow mapping (Peters & Klein 2015, Hamburger 4MSM) with soft shadows: four moments of
// normalized linear light depth averaged over a box from a summed-area table. The box comes from
// a PCSS-style blocker estimate (by default the two-moment estimate of Yang et al. 2010 on the
// first two moments; with FOUR_MOMENT_SEARCH the four-moment one of Peters et al. 2016), then
// similar triangles, so shadows harden at contacts; visibility is 1 minus the 4MSM shadow
// intensity over that box, with the light-bleeding reduction of Lauritzen 2007 (as VSSM's).
// OUTPUT: 0 visibility, 1 blocker depth, 2 filter radius.
#include "../shadow/common/shadow_space.glsl"
#include "../shadow/common/moments.glsl"

in vec2 vUv;
uniform sampler2D uPosition;
uniform sampler2D uGeometry;
uniform float uMomentBias;
uniform float uBleedReduction;
uniform bool uCentred;
uniform float uMinPenumbra;
uniform float uMaxPenumbra;
uniform float uMaxSearch;

layout(location = 0) out vec4 oValue;

// The box mean of (z, z^2, z^3, z^4), restored from the optimized basis: in float, and in double
// for msm.centred.
vec4 filteredMoments(vec2 uv, float radius) {
  vec4 m = boxMoments(uv, radius);
#ifdef OPTIMIZED
  m = restoreOptimizedMoments(m);
#endif
  return m;
}
dvec4 filteredMomentsExact(vec2 uv, float radius) {
  dvec4 m = boxMomentsExact(uv, radius);
#ifdef OPTIMIZED
  m = restoreOptimizedMoments(m);
#endif
  return m;
}

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 geometry = texelFetch(uGeometry, px, 0);
  float mask = geometry.w < 0.5 ? 0.0 : 1.0;
  vec3 q = shadowReceiver(texelFetch(uPosition, px, 0).xyz, mask > 0.0 ? normalize(geometry.xyz) : vec3(0.0));
  vec3 coord;
  bool inside = shadowCoord2D(q, coord);
  float zR = dot(q - uLightPosition, uLightDirection);
  float t = (zR - uLightNear) / (uLightFar - uLightNear) - uConstantBias;

  float visibility = 1.0, blockerShown = 0.0, radius = 0.0;
  vec3 n = mask > 0.0 ? normalize(geometry.xyz) : vec3(0.0);
  if (mask > 0.0 && shadowFacesAway(texelFetch(uPosition, px, 0).xyz, n)) {
    visibility = 0.0;
  } else if (inside && mask > 0.0) {
    float search = clamp(shadowSearchTexels(zR), 1.0, uMaxSearch);
    float zOcc;
#ifdef FOUR_MOMENT_SEARCH
    bool blocked = momentBlockerDepth4(filteredMoments(coord.xy, search), t, uMomentBias, zOcc);
#else
    bool blocked = momentBlockerDepth(filteredMoments(coord.xy, search).xy, t, 1e-7, zOcc);
#endif
    if (blocked) {
      radius = clamp(shadowPenumbraTexels(zR, uLightNear + zOcc * (uLightFar - uLightNear)), uMinPenumbra, uMaxPenumbra);
      // uCentred: the bound from the moments about t (moments.glsl, momentsAbout).
      float shadow = uCentred ? hamburger4Msm(momentsAbout(filteredMomentsExact(coord.xy, radius), t, uMomentBias), 0.0, 0.0)
                              : hamburger4Msm(filteredMoments(coord.xy, radius), t, uMomentBias);
      visibility = reduceBleeding(1.0 - shadow, uBleedReduction);
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
