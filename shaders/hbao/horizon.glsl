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
// the measure between the horizon and the biased tangent plane.
#ifndef HBAO_INTEGRAL
#define HBAO_INTEGRAL 1
#endif

const float kHalfPi = 1.57079632679490;

struct Slice {
  vec3 v, d;     // unit view vector and in-slice tangent (d perpendicular to v)
  float n;       // angle of the projected normal from v, towards d
  float np;      // length of the projected normal
  float cosN, sinN;
  float lo, hi;  // the hemisphere's part of this half-slice: theta in [lo, hi]
};

Slice makeSlice(vec3 v, vec3 normal, vec3 tangent) {
  Slice s;
  s.v = v;
  vec3 d = tangent - dot(tangent, v) * v;
  s.d = d * inversesqrt(max(dot(d, d), 1e-20));
  float nv = dot(normal, v), nd = dot(normal, s.d);
  s.np = sqrt(nv * nv + nd * nd);
  s.n = s.np > 1e-6 ? atan(nd, nv) : 0.0;
  s.cosN = cos(s.n);
  s.sinN = sin(s.n);
  s.lo = max(0.0, s.n - kHalfPi);
  s.hi = min(kPi, s.n + kHalfPi);
  return s;
}

// The slice measure of the directions from lo up to theta (increasing in theta).
float sliceMeasure(Slice s, float theta) {
#if HBAO_INTEGRAL == 1
  return 0.25 * s.np * (s.cosN - cos(2.0 * theta - s.n) + 2.0 * theta * s.sinN);
#else
  return -cos(theta);
#endif
}

// Angle from v towards d of the offset to a tap (taps of this direction lie on d's side).
float tapAngle(Slice s, vec3 offset) { return atan(max(dot(offset, s.d), 0.0), dot(offset, s.v)); }
