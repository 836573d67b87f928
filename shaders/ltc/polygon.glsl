// The cosine integral over a spherical polygon (Heitz, Dupuy, Hill & Neubelt 2016, "Real-time
// polygonal-light shading with linearly transformed cosines"; techniques/ltc/README.md). The
// polygon's vertices are directions from the shading point in a frame whose z axis is the clamped
// cosine's axis (the shading normal for the diffuse term, the LTC's axis after M^-1 for the
// specular term); they need not be unit vectors. The result is the form factor
// (1/pi) * integral of max(0, cos theta) over the polygon: 1 for a polygon covering the hemisphere.
// LTC_EDGE_ACOS selects the textbook edge formula (ltc.edge=acos); the default is the rational fit.
#include "../common/constants.glsl"

const int kLtcMaxVertices = 8;  // the largest polygon the path takes (a rectangle has 4)
// Clipping adds one vertex per edge that crosses the horizon and keeps the vertices above it:
// at most n + n/2 = 12 for a (possibly non-convex) octagon; a convex polygon gains at most one.
const int kLtcMaxClipped = 12;

// Unit vector along v, or 0 for a zero vector (the shading point on a vertex of the light):
// the edges at that vertex then contribute nothing instead of NaN.
vec3 ltcSafeNormalize(vec3 v) {
  float l2 = dot(v, v);
  return l2 > 1e-30 ? v * inversesqrt(l2) : vec3(0.0);
}

// The vector form factor of the great arc from a to b (unit vectors):
// acos(a.b) / (2 pi) * normalize(a x b) = (theta / sin theta) / (2 pi) * (a x b).
vec3 ltcEdgeVector(vec3 a, vec3 b) {
  // exercise(ltc-edge): begin
  // task: Return the vector form factor of the arc from a to b (unit vectors, or 0 when guarded):
  // task: theta / (2 pi sin theta) * cross(a, b), theta the angle between them, x = dot(a, b).
  // task: LTC_EDGE_ACOS defined (ltc.edge=acos): theta = acos(x) with x clamped to [-1, 1] and
  // task: 1 / sin theta = inversesqrt(max(1 - x * x, 1e-7)). Otherwise the rational fit of
  // task: theta / (2 pi sin theta) (no 1/(2 pi) after it): y = |x|,
  // task: p = 0.8543985 + (0.4965155 + 0.0145206 y) y, q = 3.4175940 + (4.1616724 + y) y,
  // task: f = x > 0 ? p / q : 0.5 * inversesqrt(max(1 - x * x, 1e-7)) - p / q.
  // task: kInvPi is 1/pi.
  float x = dot(a, b);
#ifdef LTC_EDGE_ACOS
  x = clamp(x, -1.0, 1.0);
  float f = acos(x) * inversesqrt(max(1.0 - x * x, 1e-7)) * (0.5 * kInvPi);
#else
  float y = abs(x);
  float p = 0.8543985 + (0.4965155 + 0.0145206 * y) * y;
  float q = 3.4175940 + (4.1616724 + y) * y;
  float f = x > 0.0 ? p / q : 0.5 * inversesqrt(max(1.0 - x * x, 1e-7)) - p / q;
#endif
  return cross(a, b) * f;
  // exercise: stub
  // return vec3(0.0); // no edge contributes: the light adds nothing
  // exercise: end
}

// Sum of the edges' vector form factors of the closed polygon v[0..n-1] (normalised here). Its
// z component is the signed form factor of the polygon when every vertex is above the horizon;
// its length and direction feed the sphere approximation of clipping (ltc.horizon=sphere).
vec3 ltcPolygonVector(vec3 v[kLtcMaxClipped], int n) {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < n; ++i)
    sum += ltcEdgeVector(ltcSafeNormalize(v[i]), ltcSafeNormalize(v[(i + 1) % n]));
  return sum;
}

// Clips the polygon v[0..n-1] to the upper hemisphere z >= 0 (Sutherland-Hodgman against the
// plane z = 0 through the shading point) and returns the new vertex count (0 when nothing is left).
int ltcClipToHorizon(inout vec3 v[kLtcMaxClipped], int n) {
  // exercise(ltc-clip): begin
  // task: Keep the part of the polygon v[0..n-1] with z >= 0, in order, in v, and return its
  // task: vertex count. Walk the edges (v[i], v[(i + 1) % n]): keep v[i] if v[i].z >= 0, and
  // task: where the edge crosses z = 0 (one end above, one below), add the point where it does:
  // task: mix(a, b, a.z / (a.z - b.z)). Build the result in a local array of kLtcMaxClipped
  // task: (at most 12 vertices for n <= kLtcMaxVertices), then copy it back into v.
  vec3 kept[kLtcMaxClipped];
  int m = 0;
  for (int i = 0; i < n; ++i) {
    vec3 a = v[i], b = v[(i + 1) % n];
    bool aAbove = a.z >= 0.0, bAbove = b.z >= 0.0;
    if (aAbove) kept[m++] = a;
    if (aAbove != bAbove) kept[m++] = mix(a, b, a.z / (a.z - b.z));
  }
  for (int i = 0; i < m; ++i) v[i] = kept[i];
  return m;
  // exercise: stub
  // return n; // no clipping: the part below the horizon leaks in
  // exercise: end
}

// The signed form factor of the polygon v[0..n-1] clipped to the upper hemisphere: positive when
// its vertices turn counter-clockwise about +z (seen from above: the order ltcRectPolygon gives a
// light's emitting face seen from the front), negative for the opposite winding (its back).
float ltcClippedFormFactor(vec3 v[kLtcMaxClipped], int n) {
  int m = ltcClipToHorizon(v, n);
  if (m < 3) return 0.0;
  return ltcPolygonVector(v, m).z;
}
