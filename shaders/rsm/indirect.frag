#version 450 core
// rsm's estimator (techniques/rsm/README.md), at the indirect resolution: texel k stands for frame
// pixel k * uScale. For the surface point x with shading normal n it sums the irradiance of the
// light-space G-buffer's texels around x's projection (s, t), each a Lambertian VPL radiating
// I_p(w) = (Phi_p / pi) max(0, n_p . w):
//   E_p(x, n) = Phi_p / pi * max(0, n_p . (x - x_p)) max(0, n . (x_p - x)) / |x - x_p|^4
// with |x - x_p| clamped below by rsm.distance_clamp texel footprints of x_p.
//   pattern (the paper's): sample j at (s, t) + r_max xi1 (sin 2 pi xi2, cos 2 pi xi2), weight
//     w_j = (k + 1) pi r_max^2 res^2 xi1^k / N for the exponent k. The pattern's density in map uv
//     is 1 / (2 pi r_max^2 xi1), so with k = 1 each sample is E_p times res^2 / density / N: an
//     unbiased estimate of the sum over the disc's texels. k = 2 (published) over-weights the rim.
//   ALL_TEXELS: the sum over every texel whose centre lies within r_max (the sampling reference).
// Output: rgb the irradiance times rsm.intensity, a the VPLs in front of both normals divided by
// the VPLs examined (rsm.samples; ALL_TEXELS: pi (r_max res)^2, the disc's nominal texel count)
// for the rsm.vpl_count view. Sky pixels: 0.
#include "common/rsm.glsl"
#include "../common/constants.glsl"

in vec2 vUv;
uniform sampler2D uPosition; // gbuffer.position: xyz world, w linear depth (0 on sky)
uniform sampler2D uNormal;   // gbuffer.normal: xyz shading normal
uniform int uScale;
uniform ivec2 uFullSize;
uniform int uSamples;         // rsm.samples
uniform float uRMax;          // rsm.r_max, map uv
uniform int uWeightExponent;  // rsm.weight_exponent, 1 or 2
uniform float uDistanceClamp; // rsm.distance_clamp, texel footprints
uniform float uIntensity;     // rsm.intensity
#ifdef ALL_TEXELS
uniform int uReach;           // rows and columns examined: centre +- uReach
uniform int uRowBegin, uRowEnd;
#endif

layout(location = 0) out vec4 oRaw;

uint hash32(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}
float unitFloat(uint x) { return float(x >> 8) * (1.0 / 16777216.0); }
float radicalInverse(uint i) { return float(bitfieldReverse(i)) * 2.3283064365386963e-10; }

// The irradiance at x (normal n) from the VPL v of face `face`; `front` is set when v lies in front
// of both normals (it contributes).
vec3 vplIrradiance(RsmVpl v, int face, vec3 x, vec3 n, out bool front) {
  // exercise(rsm-irradiance): begin
  // task: The irradiance at the receiver x (unit shading normal n) from one VPL v: v.flux (Phi_p,
  // task: rgb), v.normal (n_p, unit), v.position (x_p). A Lambertian VPL radiates
  // task: I_p(w) = (Phi_p / pi) max(0, n_p . w), so with d = x - x_p (unnormalised):
  // task:   E = Phi_p / pi * max(0, n_p . d) * max(0, n . (-d)) / |d|^4.
  // task: Clamp |d| below by dmin = uDistanceClamp * rsmTexelFootprint(v.position, face) (the
  // task: corner spike) and never divide by 0 (a VPL at x itself gives 0). Set `front` when both
  // task: dot products are > 0. Use kPi.
  vec3 d = x - v.position;
  float emit = max(dot(v.normal, d), 0.0);
  float receive = max(dot(n, -d), 0.0);
  front = emit > 0.0 && receive > 0.0;
  float dmin = uDistanceClamp * rsmTexelFootprint(v.position, face);
  float dist2 = max(max(dot(d, d), dmin * dmin), 1e-20);
  return v.flux * (emit * receive / (kPi * dist2 * dist2));
  // exercise: stub
  // // no VPL contributes: 0 indirect light everywhere
  // front = false;
  // return vec3(0.0);
  // exercise: end
}

void main() {
  ivec2 px = min(ivec2(gl_FragCoord.xy) * uScale, uFullSize - 1);
  vec4 position = texelFetch(uPosition, px, 0);
  oRaw = vec4(0.0);
  if (position.w <= 0.0) return;
  vec3 x = position.xyz;
  vec3 n = texelFetch(uNormal, px, 0).xyz;
  n = dot(n, n) > 0.0 ? normalize(n) : n;
  int face;
  vec2 s;
  if (!rsmLocate(x, face, s)) return; // behind a spot light: no projection, no VPLs
  float res = float(uRsmResolution);
  vec3 sum = vec3(0.0);
  float contributing = 0.0, examined = 0.0;
#ifdef ALL_TEXELS
  // Rows uRowBegin..uRowEnd (texel offsets from the centre's row, within +-uReach) in this draw:
  // the pass splits the disc into bands of at most ~60000 texels, blended additively, because
  // llvmpipe stops a loop nest after 65535 iterations per invocation.
  ivec2 centre = ivec2(floor(s * res));
  for (int j = max(-uReach, uRowBegin); j <= min(uReach, uRowEnd); ++j)
    for (int i = -uReach; i <= uReach; ++i) {
      vec2 t = (vec2(centre + ivec2(i, j)) + 0.5) / res;
      if (distance(t, s) > uRMax) continue;
      int f;
      vec2 uv;
      RsmVpl v;
      if (!rsmResolve(face, t, f, uv) || !rsmFetchUv(uv, f, v)) continue;
      bool front;
      sum += vplIrradiance(v, f, x, n, front);
      contributing += front ? 1.0 : 0.0;
    }
  examined = kPi * uRMax * uRMax * res * res; // the disc's texels, nominally (additive over the bands)
#else
  // The per-pixel offsets of the pattern (a Cranley-Patterson rotation: each sample uniform).
  uint seed = hash32(uint(px.x) + 65536u * uint(px.y));
  float shift = unitFloat(seed), turn = unitFloat(hash32(seed ^ 0x9e3779b9u));
  // exercise(rsm-pattern): begin
  // task: The paper's pattern around the projection s (map uv of `face`), N = uSamples samples:
  // task: xi1 = fract((j + 0.5) / N + shift), xi2 = fract(radicalInverse(j) + turn) (shift and
  // task: turn: the per-pixel offsets above),
  // task: t = s + uRMax * xi1 * vec2(sin(2 pi xi2), cos(2 pi xi2)).
  // task: rsmResolve(face, t, f, uv) gives the face and uv storing t (false: no VPL there);
  // task: rsmFetchUv(uv, f, v) the VPL (false: empty texel). Add each VPL's vplIrradiance(v, f,
  // task: x, n, front) times w = (k + 1) pi uRMax^2 res^2 xi1^k / N, k = uWeightExponent (the
  // task: disc's area density for k = 1: unbiased); count `front` in `contributing`.
  float k = float(uWeightExponent);
  float norm = (k + 1.0) * kPi * uRMax * uRMax * res * res / float(uSamples);
  for (int j = 0; j < uSamples; ++j) {
    float xi1 = fract((float(j) + 0.5) / float(uSamples) + shift);
    float xi2 = fract(radicalInverse(uint(j)) + turn);
    vec2 t = s + uRMax * xi1 * vec2(sin(2.0 * kPi * xi2), cos(2.0 * kPi * xi2));
    int f;
    vec2 uv;
    RsmVpl v;
    if (!rsmResolve(face, t, f, uv) || !rsmFetchUv(uv, f, v)) continue;
    bool front;
    sum += norm * pow(xi1, k) * vplIrradiance(v, f, x, n, front);
    contributing += front ? 1.0 : 0.0;
  }
  // exercise: stub
  // // no sample is taken: 0 indirect light everywhere
  // exercise: end
  examined = float(uSamples);
#endif
  oRaw = vec4(uIntensity * sum, contributing / max(examined, 1.0));
}
