#version 450 core
// ltc: the radiance every rectangular light adds at a pixel, unshadowed, through linearly
// transformed cosines (Heitz, Dupuy, Hill & Neubelt 2016; techniques/ltc/README.md). Diffuse: the
// light's polygon in the shading normal's frame, its clipped cosine integral (the form factor)
// times L_e and the diffuse albedo. Specular: the same polygon taken through the fitted M^-1 of
// the pixel's (roughness, theta_v) cell, times L_e and the lobe's scale
// F0 (magnitude - fresnel) + fresnel. Writes `arealight` (rgb, 0 on background) or, with
// LTC_OUTPUT_DIFFUSE / LTC_OUTPUT_SPECULAR / LTC_OUTPUT_FIT_ERROR, one of the debug views.
#include "../common/lights.glsl"
#include "polygon.glsl"
#include "lut.glsl"

uniform sampler2D uPosition;
uniform sampler2D uNormal;
uniform sampler2D uGeometry;
uniform sampler2D uAlbedo;
uniform sampler2D uMaterial;
uniform vec3 uCameraPosition;
uniform int uDiffuseFresnel;   // ltc.diffuse_fresnel: 0 none, 1 average
#ifdef LTC_HORIZON_SPHERE
uniform sampler2D uLtcSphere;  // horizon-clipped form factor of a sphere / |F|, at (z/2 + 1/2, |F|)
#endif

layout(location = 0) out vec4 oValue;

// The rectangle's corners relative to p, counter-clockwise about the axis opposite to the
// direction it emits in (so the emitting face, seen from in front, integrates to a positive value).
void ltcRectPolygon(GpuLight light, vec3 p, out vec3 q[kLtcMaxVertices]) {
  vec3 c = light.positionType.xyz - p;
  vec3 r = light.rectRight.xyz * (0.5 * light.rectRight.w);
  vec3 u = light.rectUp.xyz * (0.5 * light.rectUp.w);
  if (dot(cross(r, u), light.directionRange.xyz) > 0.0) u = -u;
  q[0] = c - r - u;
  q[1] = c + r - u;
  q[2] = c + r + u;
  q[3] = c - r + u;
}

// The form factor of the light's polygon q[0..n-1] (relative to p, world axes) for the clamped
// cosine M^-1 (`inverse`; `diffuse`: M = I) in the (n, v) frame `frame`, for a light seen from its
// emitting side (`front`) or not.
float ltcFormFactor(vec3 q[kLtcMaxVertices], int n, mat3 frame, mat3 inverse, bool diffuse, bool front,
                    bool twoSided) {
  if (!front && !twoSided) return 0.0;
  vec3 v[kLtcMaxVertices];
  for (int i = 0; i < kLtcMaxVertices && i < n; ++i) v[i] = frame * q[i];
#ifdef LTC_HORIZON_SPHERE
  // Heitz 2017: the unclipped polygon's vector form factor F, replaced by a sphere of the same F
  // whose horizon-clipped form factor is tabulated.
  if (!diffuse)
    for (int i = 0; i < kLtcMaxVertices && i < n; ++i) v[i] = inverse * v[i];
  vec3 f = ltcPolygonVector(v, n);
  if (!front) f = -f; // the back face winds the other way
  float len = length(f);
  if (len <= 0.0) return 0.0;
  vec2 uv = vec2(f.z / len * 0.5 + 0.5, min(len, 1.0));
  uv = uv * ((uLtcSize - 1.0) / uLtcSize) + 0.5 / uLtcSize;
  return len * texture(uLtcSphere, uv).r;
#else
  // The specular term is clipped twice: to the surface's horizon (the definition integrates over
  // the shading normal's hemisphere), then, after M^-1, to the clamped cosine's (the LTC's
  // support, a hemisphere that M tilts partly below the surface's: without the first clip a light
  // just below the horizon leaks into the specular term). The diffuse term needs the first only.
  float e = diffuse ? ltcClippedPolygonVector(v, n).z : ltcDoublyClippedVector(v, n, inverse).z;
  return twoSided ? abs(e) : max(e, 0.0);
#endif
}

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  if (texelFetch(uGeometry, px, 0).w < 0.5) {
    oValue = vec4(0.0);
    return;
  }
  vec3 p = texelFetch(uPosition, px, 0).xyz;
  vec3 n = normalize(texelFetch(uNormal, px, 0).xyz);
  vec4 albedo = texelFetch(uAlbedo, px, 0);
  float roughness = clamp(texelFetch(uMaterial, px, 0).a, 0.0, 1.0);
  vec3 v = normalize(uCameraPosition - p);
  float cosThetaV = clamp(dot(n, v), 0.0, 1.0);

  vec2 uv = ltcLutUv(roughness, cosThetaV);
  vec4 scale = texture(uLtcScale, uv);
#ifdef LTC_OUTPUT_FIT_ERROR
  oValue = vec4(vec3(scale.w), 1.0);
  return;
#endif
  mat3 frame = ltcFrame(n, v);
  mat3 inverse = ltcInverseMatrix(texture(uLtcMatrix, uv));

  vec3 diffuse = vec3(0.0), specular = vec3(0.0);
  for (int i = 0; i < uLightCount; ++i) {
    GpuLight light = uLights[i];
    if (int(light.positionType.w) != kLightRect) continue;
    // The shading point on the light's plane sees it edge-on: no light (and no 0/0 below).
    float side = dot(p - light.positionType.xyz, light.directionRange.xyz);
    if (abs(side) < 1e-6) continue;
    bool twoSided = light.spotCos.z > 0.5;
    vec3 q[kLtcMaxVertices];
    ltcRectPolygon(light, p, q);
    vec3 radiance = light.colorIntensity.rgb * light.colorIntensity.w;
    diffuse += radiance * ltcFormFactor(q, 4, frame, inverse, true, side > 0.0, twoSided);
    specular += radiance * ltcFormFactor(q, 4, frame, inverse, false, side > 0.0, twoSided);
  }

  float metallic = albedo.a;
  vec3 f0 = mix(vec3(0.04), albedo.rgb, metallic);
  vec3 diffuseAlbedo = albedo.rgb * (1.0 - metallic);
  // The definition's (1 - F(v.h)) varies over the light; `average` takes its cosine-weighted mean
  // over the hemisphere, (1 - F0)(1 - diffuse_fresnel), `none` drops it (the README's (1 - F) gap).
  if (uDiffuseFresnel == 1) diffuseAlbedo *= (1.0 - f0) * (1.0 - scale.z);
  vec3 specularScale = f0 * (scale.x - scale.y) + scale.y;
#if defined(LTC_OUTPUT_DIFFUSE)
  oValue = vec4(diffuse * diffuseAlbedo, 1.0);
#elif defined(LTC_OUTPUT_SPECULAR)
  oValue = vec4(specular * specularScale, 1.0);
#else
  oValue = vec4(diffuse * diffuseAlbedo + specular * specularScale, 1.0);
#endif
}
