#version 450 core
// Transparent surfaces without a transparency technique: lit by every light (unshadowed), drawn
// back to front per object with premultiplied over-blending (ONE, ONE_MINUS_SRC_ALPHA). The colour
// is clamped to 65504 before the alpha weighting, so the blend onto a clamped opaque colour stays
// finite too; each clamped fragment is counted (docs/stages.md "The HDR clamp").
#include "material.glsl"
#include "../common/brdf.glsl"
#include "../common/hdr.glsl"
#include "../common/lights.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vTangent;
in vec2 vUv;

uniform vec3 uCameraPosition;
uniform vec3 uAmbient;

layout(location = 0) out vec4 oColor;

void main() {
  SurfaceMaterial m = sampleMaterial(vUv);
  vec3 n = shadingNormal(vNormal, vTangent, vUv);
  if (!gl_FrontFacing) n = -n;
  vec3 v = normalize(uCameraPosition - vWorldPos);
  vec3 color = m.emissive + uAmbient * m.baseColor.rgb * (1.0 - m.metallic) * m.occlusion;
  for (int i = 0; i < uLightCount; ++i) {
    vec3 l;
    vec3 e = lightIrradiance(i, vWorldPos, l);
    color += evaluateBrdfCos(n, v, l, m.baseColor.rgb, m.metallic, m.roughness) * e;
  }
  float alpha = clamp(m.baseColor.a, 0.0, 1.0);
  oColor = vec4(clampHdr(color) * alpha, alpha);
}
