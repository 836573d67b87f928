#version 450 core
// SDF soft shadows (Hart 1996 sphere tracing; penumbra estimators of Quilez 2010 and 2018): from
// the shading point p lifted by tmin along its normal, march towards light 0 through the scene's
// distance volume, stepping by the safe distance h (clamped to [min step, max step]), and keep the
// running minimum of the estimated visible fraction. A step with h below the hit threshold is an
// occluder (0). The march ends at the light (spot, point) or where it leaves the volumes' union
// box (nothing lies outside). Running out of steps keeps the running minimum (not 1) and is counted.
// OUTPUT selects what is written: 0 visibility, 1 steps / max steps, 2 the SDF slice view.
#include "../sdf/common/sdf_volume.glsl"

in vec2 vUv;
uniform sampler2D uPosition;
uniform sampler2D uGeometry;
uniform bool uDirectional;
uniform vec3 uLightPoint;    // spot, point
uniform vec3 uLightTravel;   // directional: the direction light travels
uniform float uSinAngle;     // directional: sin of light0.angle
uniform float uLightRadius;  // spot, point: light0.radius
uniform float uKScale;
uniform bool uImproved;
uniform int uSteps;
uniform float uMinStep;
uniform float uMaxStep;      // >= uMinStep
uniform float uTmin;
uniform float uHitEpsilon;
uniform float uSliceHeight;

#if OUTPUT == 0
layout(std430, binding = 0) buffer Counts { uint uExhausted; };
#endif

layout(location = 0) out vec4 oValue;

struct March {
  float visibility;
  int steps;
  bool exhausted;
};

// The hit threshold at x, t: epsilon grows with t (the SDF's error is relative) and never falls
// below a few float spacings of x (|x| ~ 4e3 has a spacing of 5e-4).
float hitThreshold(vec3 x, float t) {
  vec3 a = abs(x);
  return max(uHitEpsilon * max(1.0, t), 4.0 * 1.1920929e-7 * max(a.x, max(a.y, a.z)));
}

// Sphere-trace o + t*l for t in [uTmin, tEnd) with hardness k (k < 0: a zero-size light, a hit test).
March march(vec3 o, vec3 l, float tEnd, float k) {
  float res = 1.0;
  float t = uTmin;
  float previous = -1.0; // the previous step's distance; < 0 before the first step
  float step = 0.0;      // the previous step's length
  int i = 0;
  bool hit = false;
  // exercise(sdf_shadow-march): begin
  // task: Sphere tracing with the soft-shadow estimator. Loop while i < uSteps and t < tEnd: read
  // task: h = sdfDistance(o + l * t). A hit (h < hitThreshold(x, t)) sets res = 0.0, hit = true
  // task: and ends the loop. Otherwise, when k > 0 (a light with a size), lower res:
  // task: classic (uImproved false): res = min(res, k * h / t).
  // task: improved (Quilez 2018): the previous sphere (radius `previous`, `step` behind x) and this
  // task: one (radius h) meet at the point t - y on the ray, y = (h*h - previous*previous + step*step)
  // task: / (2*step), at distance d = sqrt(max(0, h*h - y*y)) from the ray (the max(0, .) keeps
  // task: rounding from making a NaN): res = min(res, k * d / (t - y)). Use it only where the spheres
  // task: meet between the two samples, 0 <= y <= step and y < h (and y < t); on the first step
  // task: (previous < 0) and elsewhere (the interpolated SDF is not exactly 1-Lipschitz, and near
  // task: tangent spheres d collapses to 0: black speckles) use the classic estimate.
  // task: Then set previous = h, step = clamp(h, uMinStep, uMaxStep), t += step, ++i.
  while (i < uSteps && t < tEnd) {
    vec3 x = o + l * t;
    float h = sdfDistance(x);
    if (h < hitThreshold(x, t)) {
      res = 0.0;
      hit = true;
      break;
    }
    if (k > 0.0) {
      // The improved estimate where the two spheres meet between the samples (0 <= y <= step,
      // y < h); elsewhere the classic one.
      float y = uImproved && previous >= 0.0 ? (h * h - previous * previous + step * step) / (2.0 * step) : -1.0;
      if (y >= 0.0 && y <= step && y < h && y < t) {
        float d = sqrt(max(0.0, h * h - y * y));
        res = min(res, k * d / (t - y));
      } else {
        res = min(res, k * h / t);
      }
    }
    previous = h;
    step = clamp(h, uMinStep, uMaxStep);
    t += step;
    ++i;
  }
  // exercise: stub
  // // no march: every point is lit
  // exercise: end
  March m;
  m.visibility = clamp(res, 0.0, 1.0);
  m.steps = i;
  m.exhausted = !hit && i >= uSteps && t < tEnd;
  return m;
}

vec3 sliceColour(vec2 uv) {
  vec3 x = uSdfOrigin + uSdfSize * vec3(uv.x, uSliceHeight, 1.0 - uv.y);
  float d = sdfDistance(x);
  float voxel = uSdfVoxel;
  float band = 0.6 + 0.4 * step(0.5, fract(abs(d) / (4.0 * voxel)));
  float edge = smoothstep(0.0, 0.5 * voxel, abs(d));
  return (d < 0.0 ? vec3(0.9, 0.15, 0.1) : vec3(band)) * edge;
}

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
#if OUTPUT == 2
  oValue = vec4(sliceColour(vUv), 1.0);
#else
  vec4 geometry = texelFetch(uGeometry, px, 0);
  vec3 p = texelFetch(uPosition, px, 0).xyz;
  float mask = geometry.w < 0.5 ? 0.0 : 1.0;
  vec3 n = mask > 0.0 ? normalize(geometry.xyz) : vec3(0.0, 1.0, 0.0);
  // Direction to the light, the light's angular radius (as sin) and where the march ends.
  vec3 o = p + n * uTmin;
  vec3 l;
  float sinTheta, tEnd;
  if (uDirectional) {
    l = -uLightTravel;
    sinTheta = uSinAngle;
    tEnd = sdfBoxExit(o, l);
  } else {
    vec3 toLight = uLightPoint - o;
    float distance = length(toLight);
    l = toLight / max(distance, 1e-20);
    sinTheta = min(uLightRadius / max(distance, 1e-20), 1.0);
    tEnd = min(distance, sdfBoxExit(o, l));
  }
  // k = k_scale / sin(theta_L), at least 1; a zero-size light has k = infinity: a pure hit test.
  float k = sinTheta > 0.0 ? max(uKScale / sinTheta, 1.0) : -1.0;
  March m;
  m.visibility = 1.0;
  m.steps = 0;
  m.exhausted = false;
  bool facesAway = dot(n, l) <= 0.0; // the light is below the surface's horizon: 0, as the reference
  if (mask > 0.0 && !facesAway) m = march(o, l, tEnd, k);
  float visibility = facesAway ? 0.0 : m.visibility;
#if OUTPUT == 1
  float shown = float(m.steps) / float(uSteps);
  oValue = vec4(vec3(shown * mask), mask);
#else
  if (m.exhausted && mask > 0.0) atomicAdd(uExhausted, 1u);
  oValue = vec4(visibility * mask);
#endif
#endif
}
