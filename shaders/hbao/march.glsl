// Per-pixel set-up and the march along one direction, shared by the AO pass (ao.frag) and the
// sample-pattern view (pattern.frag). Pixel coordinates are G-buffer pixels; the AO target may
// be smaller (half resolution), uGbufferStep G-buffer pixels per target pixel.
#include "../common/constants.glsl"
#include "horizon.glsl"

uniform sampler2D uPosition;  // xyz world position, w linear view depth
uniform sampler2D uNormal;    // xyz shading normal
uniform sampler2D uGeometry;  // w coverage
uniform ivec2 uGbufferSize;
uniform int uGbufferStep;     // 1 full resolution, 2 half
uniform vec3 uCameraPosition;
uniform vec3 uCameraRight;    // world directions of the image's +x and +y
uniform vec3 uCameraUp;
uniform vec3 uCameraForward;
uniform float uFocalPx;       // pixels per scene unit at view depth 1
uniform float uRadius;        // ao.radius, scene units
uniform float uMaxRadiusPx;   // hbao.max_radius_px
uniform int uDirections;
uniform int uSteps;
uniform float uAngleBias;     // radians
uniform float uAttenuation;
uniform bool uJitter;

struct Center {
  ivec2 px;
  vec3 p, v, n;
  float radiusPx;  // ao.radius projected at the point's depth, clamped to uMaxRadiusPx
};

bool loadCenter(ivec2 px, out Center c) {
  c.px = px;
  if (texelFetch(uGeometry, px, 0).w < 0.5) return false;
  vec4 position = texelFetch(uPosition, px, 0);
  c.p = position.xyz;
  c.v = normalize(uCameraPosition - c.p);
  c.n = normalize(texelFetch(uNormal, px, 0).xyz);
  // max() keeps the division finite for points on the camera plane; the pixel cap bounds the cost.
  c.radiusPx = min(uRadius * uFocalPx / max(position.w, 1e-6), uMaxRadiusPx);
  return true;
}

// Interleaved gradient noise (Jimenez 2014): per-pixel values in [0,1) whose 3x3 neighbourhoods
// cover the range evenly, so the blur averages the jitter away.
float gradientNoise(vec2 px) { return fract(52.9829189 * fract(dot(px, vec2(0.06711056, 0.00583715)))); }

// Rotation of the direction set (fraction of one direction's sector) and offset of the taps
// (fraction of a step) at a pixel; 0.5 and 0.5 without jitter.
vec2 pixelJitter(ivec2 px) {
  if (!uJitter) return vec2(0.5);
  return vec2(gradientNoise(vec2(px)), gradientNoise(vec2(px.yx) + vec2(13.0, 41.0)));
}

vec2 directionOf(int k, float rotation) {
  float phi = (float(k) + rotation) * (2.0 * kPi / float(uDirections));
  return vec2(cos(phi), sin(phi));
}

// Tap i of a direction, in window coordinates: from 1 pixel (never the centre's own pixel) out
// to the projected radius.
vec2 tapPoint(Center c, vec2 dir, int i, float offset) {
  float r = 1.0 + (float(i) + offset) * max(c.radiusPx - 1.0, 0.0) / float(uSteps);
  return vec2(c.px) + 0.5 + dir * r;
}

// The surface point seen through window point q, on the plane of the pixel that holds q (its
// stored position and geometric normal): exact on planar surfaces, so taps lie on the slice's
// line instead of at pixel centres up to half a pixel off it, which on surfaces seen at grazing
// angles would tilt them tens of degrees out of the tangent plane. Falls back to the pixel's
// stored position where the ray nearly grazes the plane.
vec3 surfaceAt(vec2 q, vec3 stored, vec3 geometricNormal) {
  vec2 fromCentre = (q - 0.5 * vec2(uGbufferSize)) / uFocalPx;
  vec3 ray = uCameraForward + fromCentre.x * uCameraRight + fromCentre.y * uCameraUp;
  float denom = dot(ray, geometricNormal);
  if (abs(denom) < 1e-2 * length(ray)) return stored;
  return uCameraPosition + ray * (dot(stored - uCameraPosition, geometricNormal) / denom);
}

// What happened at one tap, for the pattern view.
const int kTapNone = 0;      // not a tap of this march
const int kTapSkipped = 1;   // off-screen, background or farther than ao.radius
const int kTapBelow = 2;     // within the radius, not above the horizon so far
const int kTapRaised = 3;    // raised the horizon (occludes)

struct March {
  float occlusion;  // sum of W(r) * (measure(old horizon) - measure(new horizon))
  float open;       // the half-slice's whole measure above the tangent plane
  int watched;      // kTap* of the tap at `watch`
};

March marchDirection(Center c, vec2 dir, float offset, ivec2 watch) {
  March m = March(0.0, 0.0, kTapNone);
  Slice s = makeSlice(c.v, c.n, dir.x * uCameraRight + dir.y * uCameraUp);
  if (s.hi <= s.lo) return m;
  m.open = sliceMeasure(s, s.hi) - sliceMeasure(s, s.lo);
  float horizon = s.hi - uAngleBias;  // taps must rise above the biased tangent plane
  float horizonMeasure = sliceMeasure(s, max(horizon, s.lo));
  if (c.radiusPx < 1.0) return m;     // the whole radius lies within this pixel
  float r2 = uRadius * uRadius;
  for (int i = 0; i < uSteps; ++i) {
    vec2 q = tapPoint(c, dir, i, offset);
    ivec2 tap = ivec2(floor(q));
    int status = kTapSkipped;
    vec4 geometry = texelFetch(uGeometry, clamp(tap, ivec2(0), uGbufferSize - 1), 0);
    if (all(greaterThanEqual(tap, ivec2(0))) && all(lessThan(tap, uGbufferSize)) && geometry.w >= 0.5) {
      vec3 offsetWorld = surfaceAt(q, texelFetch(uPosition, tap, 0).xyz, normalize(geometry.xyz)) - c.p;
      float d2 = dot(offsetWorld, offsetWorld);
      if (d2 <= r2 && d2 > 0.0) {
        status = kTapBelow;
        float theta = max(tapAngle(s, offsetWorld), s.lo);
        if (theta < horizon) {
          float measure = sliceMeasure(s, theta);
          m.occlusion += (1.0 - uAttenuation * d2 / r2) * (horizonMeasure - measure);
          horizon = theta;
          horizonMeasure = measure;
          status = kTapRaised;
        }
      }
    }
    if (tap == watch) m.watched = status;
  }
  return m;
}

// Ambient occlusion at a G-buffer pixel: 1 - (sum of occlusion) / (sum of open measure) for the
// cosine integral (exactly 1 where nothing rises above the tangent plane, whatever the
// directions), 1 - mean occlusion for Bavoil's solid-angle form.
float ambientOcclusion(Center c, vec2 jitter) {
  float occlusion = 0.0, open = 0.0;
  for (int k = 0; k < uDirections; ++k) {
    March m = marchDirection(c, directionOf(k, jitter.x), jitter.y, ivec2(-1));
    occlusion += m.occlusion;
    open += m.open;
  }
#if HBAO_INTEGRAL == 1
  return open > 0.0 ? clamp(1.0 - occlusion / open, 0.0, 1.0) : 1.0;
#else
  return clamp(1.0 - occlusion / float(uDirections), 0.0, 1.0);
#endif
}
