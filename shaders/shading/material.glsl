// glTF metallic-roughness material inputs, bound by SceneGpu::draw (units 0-4).
uniform sampler2D uBaseColorTex;
uniform sampler2D uMetallicRoughnessTex;
uniform sampler2D uNormalTex;
uniform sampler2D uEmissiveTex;
uniform sampler2D uOcclusionTex;
uniform vec4 uBaseColor;
uniform float uMetallic;
uniform float uRoughness;
uniform vec3 uEmissive;
uniform float uNormalScale;
uniform float uOcclusionStrength;
uniform bool uHasNormalMap;
uniform bool uAlphaMask;
uniform float uAlphaCutoff;

struct SurfaceMaterial {
  vec4 baseColor;
  float metallic;
  float roughness;
  vec3 emissive;
  float occlusion;
};

SurfaceMaterial sampleMaterial(vec2 uv) {
  SurfaceMaterial m;
  m.baseColor = uBaseColor * texture(uBaseColorTex, uv);
  vec4 mr = texture(uMetallicRoughnessTex, uv);
  m.roughness = clamp(uRoughness * mr.g, 0.0, 1.0);
  m.metallic = clamp(uMetallic * mr.b, 0.0, 1.0);
  m.emissive = uEmissive * texture(uEmissiveTex, uv).rgb;
  m.occlusion = 1.0 + uOcclusionStrength * (texture(uOcclusionTex, uv).r - 1.0);
  return m;
}

// Shading normal from the interpolated normal, the tangent frame and the normal map.
vec3 shadingNormal(vec3 normal, vec4 tangent, vec2 uv) {
  vec3 n = normalize(normal);
  if (!uHasNormalMap) return n;
  vec3 t = tangent.xyz - n * dot(n, tangent.xyz);
  if (dot(t, t) < 1e-12) return n;
  t = normalize(t);
  vec3 b = cross(n, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
  vec3 m = texture(uNormalTex, uv).xyz * 2.0 - 1.0;
  m.xy *= uNormalScale;
  vec3 mapped = mat3(t, b, n) * m;
  return dot(mapped, mapped) > 1e-12 ? normalize(mapped) : n;
}
