// A transparent layer's fragment (docs/contract.md "Transparency"), shared by the `transparent`
// fallback pass, every transparency technique and the reference's fragment capture, so that they
// all composite the same fragments: coverage a = base colour alpha x texture alpha, clamped to
// [0, 1]; radiance C = direct light from every light (unshadowed) with the frame's BRDF + ambient x
// diffuse albedo (no AO stage: screen-space visibility belongs to the opaque surface behind) +
// emission. C is clamped to 65504 and counted (docs/stages.md "The HDR clamp"). The layer
// contributes a*C. Include after the vertex outputs of shading/surface.vert are declared
// (vWorldPos, vNormal, vTangent, vUv) and set uCameraPosition, uAmbient and the lights.
#include "material.glsl"
#include "../common/brdf.glsl"
#include "../common/hdr.glsl"
#include "../common/lights.glsl"

uniform vec3 uCameraPosition;
uniform vec3 uAmbient;

struct LayerFragment {
  vec3 radiance; // C = lit + E, at most 65504 per channel
  float alpha;   // coverage a in [0, 1]
};

LayerFragment shadeLayer() {
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
  LayerFragment f;
  f.radiance = clampHdr(color);
  f.alpha = clamp(m.baseColor.a, 0.0, 1.0);
  return f;
}
