#version 450 core
// HBAO (Bavoil, Sainz & Dimitrov 2008): uDirections screen-space directions around the pixel,
// each marched for uSteps taps from the nearest neighbouring AO texel out to ao.radius projected
// into pixels (at most uMaxRadiusPx). Along each direction the highest horizon among the surface
// points within ao.radius bounds the open part of that direction's slice of the hemisphere
// (horizon.glsl); the AO is the open fraction over all directions. View space throughout: the
// camera sits at the origin, so the view vector is -p/|p|.
#include "../ao/common/ao_common.glsl"
#include "horizon.glsl"

// 1 when hbao.attenuation > 0: each raise of the horizon is weighted by its distance, so the
// measure (an acos) is taken per raising tap; 0: unweighted, taken once per direction.
#ifndef HBAO_WEIGHTED
#define HBAO_WEIGHTED 1
#endif

uniform int uDirections;
uniform int uSteps;
uniform float uMaxRadiusPx;  // frame pixels
uniform float uAngleBias;    // radians
uniform vec2 uBiasCosSin;    // cos and sin of uAngleBias
uniform float uAttenuation;  // W(r) = 1 - uAttenuation r^2 / R^2
uniform bool uJitter;        // per-pixel rotation of the directions and offset of the taps

// The surface point seen through frame point q, on the plane of the AO texel that holds q (its
// stored depth and normal): exact on planar surfaces, so the taps lie on the direction's line
// rather than at texel centres up to half a texel off it, which on surfaces seen at grazing
// angles would tilt them tens of degrees out of the tangent plane. Where the ray nearly grazes
// that plane, or meets it behind the camera (a ray on the plane's other side from the texel's
// own: grazing planes in small frames, where q lies a large angle from the texel centre), the
// texel's own point is used.
vec3 surfaceThrough(vec2 q, ivec2 tap, vec4 texel) {
  vec3 stored = aoTexelPosition(tap, texel.w);
  vec3 ray = aoViewPosition(q, 1.0);
  float denom = dot(ray, texel.xyz);
  if (denom * denom < 1e-4 * dot(ray, ray)) return stored; // |cos| < 0.01, without a sqrt per tap
  float t = dot(stored, texel.xyz) / denom; // ray depth of the intersection
  return t > 0.0 ? ray * t : stored;
}

// How many of the taps at firstPx + (i + offset) * stepPx along unit direction dir from centre lie
// in the frame (x in [0, width), y in [0, height)): the march leaves the frame once, so clipping the
// segment once per direction replaces a bounds test per tap.
int tapsInFrame(vec2 centre, vec2 dir, float firstPx, float stepPx, float offset) {
  vec2 limit = mix(-centre, vec2(uFullSize) - centre, greaterThan(dir, vec2(0.0)));
  vec2 exitT = mix(vec2(1e30), limit / dir, greaterThan(abs(dir), vec2(1e-6)));
  float reach = min(exitT.x, exitT.y) - firstPx;  // march length inside the frame past the first tap
  if (reach <= 0.0) return 0;
  if (stepPx <= 0.0) return uSteps;
  return int(min(float(uSteps), ceil(reach / stepPx - offset)));
}

float aoEvaluate(ivec2 px, AoSurface s) {
  // ao.radius in frame pixels at this depth (the pixel cap bounds the cost near the camera); the
  // first tap is far enough to leave the centre's AO texel in every direction.
  float radiusPx = min(uRadius * aoTexelsPerUnit(s.depth) * float(uScale), uMaxRadiusPx);
  float firstPx = 1.5 * float(uScale) - 0.5;
  if (radiusPx < firstPx) return 1.0; // everything within ao.radius lies inside this texel
  float stepPx = (radiusPx - firstPx) / float(uSteps);
  float rotation = uJitter ? aoNoise(px, 0) : 0.5;
  float offset = uJitter ? aoNoise(px, 1) : 0.5;
  vec2 centre = aoFullPixel(px);
  float invScale = 1.0 / float(uScale);  // frame pixels to AO texels, without an integer division per tap
  vec3 v = normalize(-s.p);
  float r2 = uRadius * uRadius;
  float occlusion = 0.0, open = 0.0;
  // Directions 2 pi (k + rotation) / N, turned from one to the next by a fixed rotation.
  float phi = rotation * (2.0 * kPi / float(uDirections));
  vec2 dir = vec2(cos(phi), sin(phi));
  float stepAngle = 2.0 * kPi / float(uDirections);
  mat2 turn = mat2(cos(stepAngle), sin(stepAngle), -sin(stepAngle), cos(stepAngle));
  for (int k = 0; k < uDirections; ++k, dir = turn * dir) {
    Slice sl = makeSlice(v, s.n, vec3(dir, 0.0));
    if (sl.hi.a <= sl.lo.a) continue;
    float hiMeasure = sliceMeasure(sl, sl.hi);
    open += hiMeasure - sliceMeasure(sl, sl.lo);
    // A tap occludes only once it rises uAngleBias above the tangent plane. Cosine: the bias is a
    // threshold, and the first tap above it occludes from the tangent plane up, so a real
    // occluder loses nothing; solid angle: Bavoil's offset tangent t + bias.
    Angle horizon = sl.lo;
    if (sl.hi.a - uAngleBias > sl.lo.a)
      horizon = Angle(sl.hi.a - uAngleBias, sl.hi.c * uBiasCosSin.x + sl.hi.s * uBiasCosSin.y,
                      sl.hi.s * uBiasCosSin.x - sl.hi.c * uBiasCosSin.y);
    float horizonCos = horizon.c;
#if HBAO_INTEGRAL == 1
    float horizonMeasure = hiMeasure;
#else
    float horizonMeasure = sliceMeasure(sl, horizon);
#endif
    int taps = tapsInFrame(centre, dir, firstPx, stepPx, offset);
    // exercise(hbao-march): begin
    // task: The horizon march along the unit direction `dir` (frame pixels) from the frame point
    // task: `centre` of AO texel `px`. Inputs: the surface point s.p, the slice `sl` (makeSlice),
    // task: r2 = uRadius^2 and the starting horizon: horizonCos (its cosine) and horizonMeasure
    // task: (its measure, sliceMeasure). Output: the sum `occlusion` (declared above).
    // task: For each tap i < taps (the taps inside the frame):
    // task: 1. step: q = centre + dir * (firstPx + (i + offset) * stepPx), in the AO texel
    // task:    tap = clamp(ivec2(q * invScale), ivec2(0), uAoSize - 1);
    // task: 2. sample: texel = texelFetch(uAoView, tap, 0) (.xyz normal, .w linear depth); skip the
    // task:    tap when texel.w <= 0 (sky never occludes) or tap == px (the centre's own texel);
    // task: 3. the offset from P: o = surfaceThrough(q, tap, texel) - s.p, d2 = dot(o, o), and the
    // task:    tap's angle from the view vector as a cosine, c = min(tapCos(sl, o), sl.lo.c)
    // task:    (at least lo);
    // task: 4. horizon update: the tap raises the horizon when 0 < d2 <= r2 and c > horizonCos (a
    // task:    larger cosine is a higher horizon; taps beyond the radius are skipped, the march
    // task:    goes on). Then, with the attenuation W = 1 - uAttenuation * d2 / r2 and
    // task:    m = sliceMeasure(sl, angleOf(c)):
    // task:    occlusion += W * (horizonMeasure - m); horizonMeasure = m; horizonCos = c.
    // task: Optional: AO_VISIT(q / vec2(uFullSize), 1.0 if the tap raised the horizon, else 0.0)
    // task: per tap (the hbao.pattern debug view; no effect on the image). Faster, same result:
    // task: with uAttenuation = 0 (W = 1) the sum telescopes to horizonMeasure(start) -
    // task: sliceMeasure(sl, angleOf(highest c)), one angle per direction (the macro HBAO_WEIGHTED
    // task: is 0 exactly then).
    for (int i = 0; i < taps; ++i) {
      vec2 q = centre + dir * (firstPx + (float(i) + offset) * stepPx);
      ivec2 tap = clamp(ivec2(q * invScale), ivec2(0), uAoSize - 1);  // q >= 0: truncation is floor
      vec4 texel = texelFetch(uAoView, tap, 0);
      bool raises = false;
      if (texel.w > 0.0 && tap != px) {  // sky (depth 0) never occludes
        vec3 offsetView = surfaceThrough(q, tap, texel) - s.p;
        float d2 = dot(offsetView, offsetView);
        float c = min(tapCos(sl, offsetView), sl.lo.c);  // the tap's angle, at least lo
        raises = d2 <= r2 && d2 > 0.0 && c > horizonCos;
#if HBAO_WEIGHTED
        if (raises) {
          float measure = sliceMeasure(sl, angleOf(c));
          occlusion += (1.0 - uAttenuation * d2 / r2) * (horizonMeasure - measure);
          horizonMeasure = measure;
        }
#endif
        horizonCos = raises ? c : horizonCos;
      }
      AO_VISIT(q / vec2(uFullSize), raises ? 1.0 : 0.0);
    }
#if !HBAO_WEIGHTED
    // With W = 1 each raise adds measure(old) - measure(new), so the sum telescopes to the measure
    // between the starting horizon and the highest tap: one angle (an acos) per direction, none
    // per tap.
    if (horizonCos > horizon.c) occlusion += horizonMeasure - sliceMeasure(sl, angleOf(horizonCos));
#endif
    // exercise: stub
    // // no tap raises the horizon: this direction adds no occlusion (AO 1, unoccluded)
    // exercise: end
  }
  // Cosine: 1 - occluded / open measure, exactly 1 where nothing rises above the tangent plane
  // whatever the directions. Solid angle: Bavoil's 1 - mean of (sin h - sin t) W.
#if HBAO_INTEGRAL == 1
  return open > 0.0 ? 1.0 - occlusion / open : 1.0;
#else
  return 1.0 - occlusion / float(uDirections);
#endif
}

#include "../ao/common/ao_main.glsl"
