// Horizon search of HBAO (Bavoil, Sainz & Dimitrov 2008) along one screen-space direction, in
// the slice of the hemisphere that the direction cuts: the plane through the surface point P
// that holds the view vector V (P to the camera) and the direction's world-space tangent D.
// A direction in that plane is an angle theta from V towards D; the surface's tangent plane
// crosses the slice at theta = n + pi/2, n being the angle of the normal projected into it.
//
// Two measures of the part of the slice above the horizon (HBAO_INTEGRAL):
//  1 cosine: I(theta) = |Np|/4 (cos n - cos(2 theta - n) + 2 theta sin n), the integral of
//    |Np| cos(t - n) sin t dt from 0 to theta: summed over directions it is the cosine-weighted
//    visible solid angle, (1/pi) of which is the ao stage's quantity (the slice form of the
//    cosine integral, as in Jimenez et al. 2016).
//  0 solid angle: -cos(theta) = sin(elevation) - 1, Bavoil's sin h - sin t with elevations
//    measured from the plane perpendicular to V.
// Each tap that raises the horizon adds W(r) (measure(old) - measure(new)), W(r) = 1 -
// attenuation * r^2 / R^2 (Bavoil's per-sample attenuation), so with attenuation 0 the sum is
// the measure between the highest horizon and the tangent plane (cosine) or the tangent plane
// raised by the angle bias (solid angle, Bavoil's t + bias).
#ifndef HBAO_INTEGRAL
#define HBAO_INTEGRAL 1
#endif

// An angle with its cosine and sine (the march works with cosines and takes an acos only when a
// tap raises the horizon).
struct Angle {
  float a, c, s;
};

struct Slice {
  vec3 v, d;      // unit view vector and in-slice tangent (d perpendicular to v)
  float n;        // angle of the projected normal from v, towards d
  float np;       // length of the projected normal
  float cosN, sinN;
  Angle lo, hi;   // the hemisphere's part of this half-slice: theta in [lo, hi]
};

Slice makeSlice(vec3 v, vec3 normal, vec3 tangent) {
  Slice s;
  s.v = v;
  vec3 d = tangent - dot(tangent, v) * v;
  s.d = d * inversesqrt(max(dot(d, d), 1e-20));
  float nv = dot(normal, v), nd = dot(normal, s.d);
  s.np = sqrt(nv * nv + nd * nd);
  bool degenerate = s.np < 1e-6;  // the normal is perpendicular to the slice
  s.n = degenerate ? 0.0 : atan(nd, nv);
  s.cosN = degenerate ? 1.0 : nv / s.np;
  s.sinN = degenerate ? 0.0 : nd / s.np;
  // hi = min(pi, n + pi/2), lo = max(0, n - pi/2); cos(n + pi/2) = -sin n, sin(n + pi/2) = cos n.
  s.hi = s.n <= kHalfPi ? Angle(s.n + kHalfPi, -s.sinN, s.cosN) : Angle(kPi, -1.0, 0.0);
  s.lo = s.n > kHalfPi ? Angle(s.n - kHalfPi, s.sinN, -s.cosN) : Angle(0.0, 1.0, 0.0);
  return s;
}

// The slice measure of the directions from 0 up to angle t (increasing in t).
float sliceMeasure(Slice s, Angle t) {
#if HBAO_INTEGRAL == 1
  // exercise(hbao-slice-integral): begin
  // task: The cosine-weighted measure of the slice's directions from the view vector (angle 0) up
  // task: to the angle t, n being the angle of the normal projected into the slice:
  // task:   I(t) = integral from 0 to t of |Np| cos(theta - n) sin(theta) d theta
  // task:        = |Np| / 4 * (cos n - cos(2t - n) + 2 t sin n).
  // task: Inputs: s.np = |Np|, s.cosN = cos n, s.sinN = sin n (s.n = n), and t.a, t.c, t.s = t,
  // task: cos t and sin t. Return I(t).
  // task: Hint: cos(2t - n) = cos 2t cos n + sin 2t sin n needs no trigonometric call.
  // cos(2t - n) = cos 2t cos n + sin 2t sin n
  float cos2tn = (2.0 * t.c * t.c - 1.0) * s.cosN + 2.0 * t.s * t.c * s.sinN;
  return 0.25 * s.np * (s.cosN - cos2tn + 2.0 * t.a * s.sinN);
  // exercise: stub
  // // every slice measures 0: no direction is open and none occluded, and hbao.frag returns AO 1
  // // (unoccluded) when the open measure is 0
  // return 0.0;
  // exercise: end
#else
  return -t.c;
#endif
}

// The angle whose cosine is c, in [0, pi] (only the cosine integral needs the angle itself).
Angle angleOf(float c) {
  c = clamp(c, -1.0, 1.0);
#if HBAO_INTEGRAL == 1
  return Angle(acos(c), c, sqrt(1.0 - c * c));
#else
  return Angle(0.0, c, sqrt(1.0 - c * c));
#endif
}

// Cosine of the angle from v towards d of the offset to a tap (taps of this direction lie on d's
// side; the part of the offset out of the slice's plane is ignored). Decreasing in the angle.
float tapCos(Slice s, vec3 offset) {
  float x = dot(offset, s.v), y = max(dot(offset, s.d), 0.0);
  return x * inversesqrt(max(x * x + y * y, 1e-30));
}
