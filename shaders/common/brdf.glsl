// Metallic-roughness BRDF: Lambert diffuse + GGX (Trowbridge-Reitz) specular with the height-
// correlated Smith visibility term and Schlick's Fresnel (Karis 2013, Heitz 2014).
#include "constants.glsl"

vec3 fresnelSchlick(float cosTheta, vec3 f0) {
  float f = pow(clamp(1.0 - cosTheta, 0.0, 1.0), 5.0);
  return f0 + (1.0 - f0) * f;
}

float distributionGgx(float nDotH, float alpha) {
  float a2 = alpha * alpha;
  float d = nDotH * nDotH * (a2 - 1.0) + 1.0;
  return a2 / max(kPi * d * d, 1e-12);
}

// V = G / (4 n.l n.v), height-correlated Smith for GGX.
float visibilitySmithGgx(float nDotL, float nDotV, float alpha) {
  float a2 = alpha * alpha;
  float gv = nDotL * sqrt(nDotV * nDotV * (1.0 - a2) + a2);
  float gl = nDotV * sqrt(nDotL * nDotL * (1.0 - a2) + a2);
  return 0.5 / max(gv + gl, 1e-8);
}

// BRDF times cos(theta_l) for one light direction. roughness is perceptual (alpha = r^2; clamped
// to 0.045 so a perfect mirror stays finite under a point light).
vec3 evaluateBrdfCos(vec3 n, vec3 v, vec3 l, vec3 baseColor, float metallic, float roughness) {
  float nDotL = dot(n, l);
  if (nDotL <= 0.0) return vec3(0.0);
  float nDotV = max(dot(n, v), 1e-4);
  vec3 h = normalize(l + v);
  float nDotH = max(dot(n, h), 0.0);
  float vDotH = max(dot(v, h), 0.0);
  float alpha = max(roughness * roughness, 0.045 * 0.045);
  vec3 f0 = mix(vec3(0.04), baseColor, metallic);
  vec3 f = fresnelSchlick(vDotH, f0);
  vec3 specular = distributionGgx(nDotH, alpha) * visibilitySmithGgx(nDotL, nDotV, alpha) * f;
  vec3 diffuse = (1.0 - f) * (1.0 - metallic) * baseColor * kInvPi;
  return (diffuse + specular) * nDotL;
}
