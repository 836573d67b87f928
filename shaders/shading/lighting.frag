#version 450 core
// Deferred direct lighting of every light from the G-buffer, plus emissive and a constant
// ambient term scaled by the ao stage's output and the material occlusion, plus the indirect
// stage's irradiance, also scaled by the ao stage's output. Light 0 is scaled by the shadow
// stage's visibility; the others are unshadowed. AO never scales direct light. With
// SKIP_RECT_LIGHTS (an arealight technique is active) rectangular lights are left to that
// technique instead of being added as points, and that technique also draws their emitting faces,
// which this pass draws otherwise (common/rect_face.glsl). The result is clamped to 65504
// (docs/stages.md).
#include "../common/brdf.glsl"
#include "../common/hdr.glsl"
#include "../common/lights.glsl"
#include "../common/rect_face.glsl"

in vec2 vUv;

uniform sampler2D uPosition;
uniform sampler2D uNormal;
uniform sampler2D uGeometry;
uniform sampler2D uAlbedo;
uniform sampler2D uMaterial;
#ifdef HAS_VISIBILITY
uniform sampler2D uVisibility;
#endif
#ifdef HAS_AO
uniform sampler2D uAo;
#endif
#ifdef HAS_INDIRECT
uniform sampler2D uIndirect;
#endif
uniform vec3 uCameraPosition;
uniform mat4 uInvViewProj;
uniform vec2 uViewportSize;
uniform vec3 uAmbient;
uniform vec3 uBackground;
uniform int uEmissionClampSlot; // the G-buffer pass's counter: its emission clamp is counted here

layout(location = 0) out vec4 oColor;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 geometry = texelFetch(uGeometry, px, 0);
  vec3 p = texelFetch(uPosition, px, 0).xyz;
#ifndef SKIP_RECT_LIGHTS
  vec3 face;
  if (rectLightFaceAtPixel(gl_FragCoord.xy, uViewportSize, uInvViewProj, uCameraPosition, geometry.w >= 0.5, p, face)) {
    oColor = vec4(clampHdr(face), geometry.w >= 0.5 ? 1.0 : 0.0);
    return;
  }
#endif
  if (geometry.w < 0.5) {
    oColor = vec4(clampHdr(uBackground), 0.0);
    return;
  }
  vec4 normalOcc = texelFetch(uNormal, px, 0);
  vec4 albedoMetal = texelFetch(uAlbedo, px, 0);
  vec4 emissiveRough = texelFetch(uMaterial, px, 0);
  vec3 n = normalize(normalOcc.xyz);
  vec3 v = normalize(uCameraPosition - p);
  vec3 baseColor = albedoMetal.rgb;
  float metallic = albedoMetal.a;
  float roughness = emissiveRough.a;

  countHdrAtLimit(emissiveRough.rgb, uEmissionClampSlot);
  vec3 color = emissiveRough.rgb;
  for (int i = 0; i < uLightCount; ++i) {
#ifdef SKIP_RECT_LIGHTS
    if (int(uLights[i].positionType.w) == kLightRect) continue;
#endif
    vec3 l;
    vec3 e = lightIrradiance(i, p, l);
#ifdef HAS_VISIBILITY
    if (i == 0) e *= texelFetch(uVisibility, px, 0).r;
#endif
    color += evaluateBrdfCos(n, v, l, baseColor, metallic, roughness) * e;
  }
  float ao = 1.0;
#ifdef HAS_AO
  ao = texelFetch(uAo, px, 0).r;
#endif
  vec3 diffuseAlbedo = baseColor * (1.0 - metallic);
  color += uAmbient * diffuseAlbedo * (normalOcc.w * ao);
#ifdef HAS_INDIRECT
  color += texelFetch(uIndirect, px, 0).rgb * diffuseAlbedo * kInvPi * ao;
#endif
  oColor = vec4(clampHdr(color), 1.0);
}
