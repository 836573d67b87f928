#version 450 core
// area_mc (techniques/area_mc/README.md): the radiance every rectangular light adds at the pixel's
// surface point (docs/contract.md "Area lights"), by Monte Carlo: per light, uSamples samples, each
// one point of the rectangle (pdf 1/A over its area) and one GGX-sampled direction, combined with
// the power heuristic (Veach & Guibas 1995). The BRDF is the frame's (common/brdf.glsl), unshadowed
// and clipped to the shading normal's hemisphere. The CPU reference
// (techniques/area_mc/area_mc_model.cpp) runs the same estimator in double precision.
#include "../common/brdf.glsl"
#include "../common/lights.glsl"

uniform sampler2D uPosition;
uniform sampler2D uNormal;
uniform sampler2D uGeometry;
uniform sampler2D uAlbedo;
uniform sampler2D uMaterial;
#ifdef PATTERN_BLUE_NOISE
uniform sampler2D uNoise; // void-and-cluster ranks in [0, 1), kNoiseSize square, repeating
const int kNoiseSize = 64;
#endif
uniform vec3 uCameraPosition;
uniform int uSamples;  // per pixel per light
uniform int uStrategy; // kStrategyMis, kStrategyLight, kStrategyBrdf
uniform uint uSeed;

layout(location = 0) out vec4 oArealight;

const int kStrategyMis = 0;
const int kStrategyLight = 1;
const int kStrategyBrdf = 2;

struct RectLight {
  vec3 center, normal, right, up;
  float width, height;
  vec3 radiance;
  bool twoSided;
};

RectLight rectLight(int i) {
  GpuLight g = uLights[i];
  return RectLight(g.positionType.xyz, g.directionRange.xyz, g.rectRight.xyz, g.rectUp.xyz, g.rectRight.w,
                   g.rectUp.w, g.colorIntensity.rgb * g.colorIntensity.w, g.spotCos.z > 0.5);
}

// |cos theta'| at the light for light leaving it along `emitted` (unit), 0 from behind a one-sided face.
float emitCos(RectLight light, vec3 emitted) {
  float c = dot(emitted, light.normal);
  return light.twoSided ? abs(c) : max(c, 0.0);
}

// The density over directions of reflecting v about a GGX half vector (D(h) n.h about n):
// D(h) n.h / (4 v.h); 0 when v.h <= 0.
float ggxReflectionPdf(vec3 n, vec3 v, vec3 l, float alpha) {
  vec3 h = normalize(l + v);
  float vDotH = dot(v, h);
  if (vDotH <= 0.0) return 0.0;
  float nDotH = max(dot(n, h), 0.0);
  return distributionGgx(nDotH, alpha) * nDotH / (4.0 * vDotH);
}

// The multiple-importance-sampling weight of a sample drawn with density `pdf` when the other
// strategy would have drawn it with density `otherPdf`.
float misWeight(float pdf, float otherPdf) {
  if (uStrategy != kStrategyMis) return 1.0;
  // exercise(area_mc-mis): begin
  // task: The power heuristic with exponent 2 (Veach & Guibas 1995): w = pdf^2 / (pdf^2 + otherPdf^2).
  // task: Both densities are over solid angle at the surface point; the two weights of a direction
  // task: sum to 1, so the two strategies together count each direction once. Write it as
  // task: 1 / (1 + r^2) with r = otherPdf / pdf: near a grazing face pdf^2 overflows a float.
  float r = otherPdf / pdf;
  return 1.0 / (1.0 + r * r);
  // exercise: stub
  // return 0.0;
  // exercise: end
}

// Light-area sampling: the point of the rectangle at u (uniform, pdf 1/A over its area).
vec3 lightSample(vec3 p, vec3 n, vec3 v, vec3 baseColor, float metallic, float roughness, float alpha,
                 RectLight light, vec2 u) {
  vec3 q = light.center + (u.x - 0.5) * light.width * light.right + (u.y - 0.5) * light.height * light.up;
  vec3 d = q - p;
  float dist2 = dot(d, d);
  if (dist2 <= 0.0) return vec3(0.0);
  vec3 l = d * inversesqrt(dist2);
  float cosLight = emitCos(light, -l);
  if (cosLight <= 0.0) return vec3(0.0);
  vec3 f = evaluateBrdfCos(n, v, l, baseColor, metallic, roughness); // 0 below the horizon
  // exercise(area_mc-light): begin
  // task: Turn the area density 1/A (A = light.width * light.height) into a density over solid angle
  // task: at p: dw = dA cos(theta') / r^2, so pdf = dist2 / (A * cosLight). Return the sample's
  // task: contribution misWeight(pdf, ggxReflectionPdf(n, v, l, alpha)) * f * light.radiance / pdf.
  float pdf = dist2 / (light.width * light.height * cosLight);
  return misWeight(pdf, ggxReflectionPdf(n, v, l, alpha)) * f * light.radiance / pdf;
  // exercise: stub
  // return vec3(0.0);
  // exercise: end
}

// GGX sampling: a half vector about n, l = v reflected about it; it counts where l meets the face.
vec3 brdfSample(vec3 p, vec3 n, vec3 v, vec3 baseColor, float metallic, float roughness, float alpha,
                RectLight light, vec2 u) {
  // phi = 2 pi u.x, cos(theta_h) = sqrt((1 - u.y) / ((alpha^2 - 1) u.y + 1)); a basis about n
  // (Duff et al. 2017).
  float phi = 2.0 * kPi * u.x;
  float a2 = alpha * alpha;
  float cosTheta = sqrt(max(0.0, (1.0 - u.y) / ((a2 - 1.0) * u.y + 1.0)));
  float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float ba = -1.0 / (s + n.z);
  float bc = n.x * n.y * ba;
  vec3 t = vec3(1.0 + s * n.x * n.x * ba, s * bc, -s * n.x);
  vec3 b = vec3(bc, s + n.y * n.y * ba, -n.y);
  vec3 h = t * (sinTheta * cos(phi)) + b * (sinTheta * sin(phi)) + n * cosTheta;
  float vDotH = dot(v, h);
  if (vDotH <= 0.0) return vec3(0.0);
  vec3 l = normalize(2.0 * vDotH * h - v);
  if (dot(n, l) <= 0.0) return vec3(0.0);
  float facing = dot(l, light.normal);
  if (abs(facing) < 1e-8) return vec3(0.0);
  float dist = dot(light.center - p, light.normal) / facing;
  if (dist <= 0.0) return vec3(0.0);
  vec3 q = p + dist * l - light.center;
  if (abs(dot(q, light.right)) > 0.5 * light.width || abs(dot(q, light.up)) > 0.5 * light.height) return vec3(0.0);
  float cosLight = emitCos(light, -l);
  float pdf = ggxReflectionPdf(n, v, l, alpha);
  if (cosLight <= 0.0 || pdf <= 0.0) return vec3(0.0);
  float lightPdf = dist * dist / (light.width * light.height * cosLight);
  return misWeight(pdf, lightPdf) * evaluateBrdfCos(n, v, l, baseColor, metallic, roughness) * light.radiance / pdf;
}

// A well-mixed 32-bit hash (the "lowbias32" finalizer of C. Wellons' hash-prospector).
uint hash32(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

float unitFloat(uint x) { return float(x >> 8) * (1.0 / 16777216.0); }

// Sample s of uSamples for the 2D dimension pair `pair` (2 per light: area point, GGX direction).
vec2 samplePoint(ivec2 px, int s, int pair) {
#ifdef PATTERN_BLUE_NOISE
  // The R2 sequence (Roberts 2018: fract(s * (1/g, 1/g^2)), g the plastic number), shifted per pixel
  // and pair by the blue-noise mask (a Cranley-Patterson rotation): low discrepancy within the pixel,
  // blue-noise-distributed error between pixels.
  ivec2 o = px + ivec2(17, 41) * pair + ivec2(uSeed % 64u, (uSeed / 64u) % 64u);
  vec2 shift = vec2(texelFetch(uNoise, o & (kNoiseSize - 1), 0).r,
                    texelFetch(uNoise, (o + ivec2(kNoiseSize / 2, 11)) & (kNoiseSize - 1), 0).r);
  return fract(vec2(s + 1) * vec2(0.7548776662466927, 0.5698402909980532) + shift);
#else
  // A jittered m x m grid (m = floor(sqrt(uSamples))) for the first m^2 samples, independent uniform
  // points for the rest: every point is uniform on its own, so the mean stays unbiased.
  uint key = hash32(uSeed ^ hash32(uint(px.x) + 65536u * uint(px.y)) ^ hash32(uint(s) * 64u + uint(pair)));
  vec2 jitter = vec2(unitFloat(hash32(key)), unitFloat(hash32(key ^ 0x9e3779b9u)));
  int m = int(sqrt(float(uSamples)) + 1e-3);
  if (s < m * m) return (vec2(s % m, s / m) + jitter) / float(m);
  return jitter;
#endif
}

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  if (texelFetch(uGeometry, px, 0).w < 0.5) {
    oArealight = vec4(0.0);
    return;
  }
  vec3 p = texelFetch(uPosition, px, 0).xyz;
  vec3 n = normalize(texelFetch(uNormal, px, 0).xyz);
  vec3 v = normalize(uCameraPosition - p);
  vec4 albedoMetal = texelFetch(uAlbedo, px, 0);
  float roughness = texelFetch(uMaterial, px, 0).a;
  float alpha = max(roughness * roughness, 0.045 * 0.045);
  vec3 sum = vec3(0.0);
  int pair = 0;
  for (int i = 0; i < uLightCount; ++i) {
    if (int(uLights[i].positionType.w) != kLightRect) continue;
    RectLight light = rectLight(i);
    vec3 lightSum = vec3(0.0);
    for (int s = 0; s < uSamples; ++s) {
      if (uStrategy != kStrategyBrdf)
        lightSum += lightSample(p, n, v, albedoMetal.rgb, albedoMetal.a, roughness, alpha, light, samplePoint(px, s, pair));
      if (uStrategy != kStrategyLight)
        lightSum += brdfSample(p, n, v, albedoMetal.rgb, albedoMetal.a, roughness, alpha, light, samplePoint(px, s, pair + 1));
    }
    sum += lightSum / float(uSamples);
    pair += 2;
  }
  oArealight = vec4(sum, 1.0);
}
