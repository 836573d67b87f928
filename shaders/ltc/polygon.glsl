// The cosine integral over a spherical polygon (Heitz, Dupuy, Hill & Neubelt 2016, "Real-time
// polygonal-light shading with linearly transformed cosines"; techniques/ltc/README.md). The
// polygon's vertices are directions from the shading point in a frame whose z axis is the clamped
// cosine's axis (the shading normal for the diffuse term, the LTC's axis after M^-1 for the
// specular term); they need not be unit vectors. The result is the form factor
// (1/pi) * integral of max(0, cos theta) over the polygon: 1 for a polygon covering the hemisphere.
// LTC_EDGE_ACOS selects the textbook edge formula (ltc.edge=acos); the default is the rational fit.
#include "../common/constants.glsl"

const int kLtcMaxVertices = 8;  // the largest polygon the path takes (a rectangle has 4)

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

// Clipping to the horizon z >= 0 as the polygon's edges stream past, in order (Sutherland-Hodgman
// without a vertex array: on llvmpipe the arrays of the array version, indexed by a running count,
// lived in memory and made the pass 26 times slower). Where the polygon goes below the horizon and
// where it comes back, the clipped polygon follows the horizon between the two points.
struct LtcHorizon {
  vec3 exitPoint;   // where the polygon last went below the horizon
  vec3 firstEntry;  // where it came back above, if that happened before any exit
  bool below;       // an exit is waiting for the next entry
  bool entered;     // firstEntry is set
};

LtcHorizon ltcHorizonBegin() { return LtcHorizon(vec3(0.0), vec3(0.0), false, false); }

// The pieces of the clipped polygon that the edge a->b (the next edge of the polygon) yields, as
// a polyline p0 -> p1 (-> p2) of `count` points (0 when nothing of it is above the horizon).
int ltcClipEdge(inout LtcHorizon h, vec3 a, vec3 b, out vec3 p0, out vec3 p1, out vec3 p2) {
  p0 = a;
  p1 = b;
  p2 = b;
  // exercise(ltc-clip): begin
  // task: Clip the edge a->b to z >= 0 (a point with z = 0 counts as above) and return the pieces
  // task: as a polyline p0 -> p1 (-> p2) and its point count: both ends above: a -> b (2). Only a
  // task: above (the polygon leaves): a -> x (2), x = mix(a, b, a.z / (a.z - b.z)) the crossing;
  // task: remember x in h.exitPoint and set h.below. Only b above (it comes back): if h.below,
  // task: the horizon from the exit, h.exitPoint -> x -> b (3), and clear h.below; otherwise
  // task: x -> b (2), and keep x in h.firstEntry with h.entered = true (ltcClipClose joins them).
  // task: Neither above: 0.
  bool aAbove = a.z >= 0.0, bAbove = b.z >= 0.0;
  if (aAbove && bAbove) return 2;
  if (!aAbove && !bAbove) return 0;
  vec3 x = mix(a, b, a.z / (a.z - b.z));
  if (aAbove) {
    p1 = x;
    h.exitPoint = x;
    h.below = true;
    return 2;
  }
  if (h.below) {
    p0 = h.exitPoint;
    p1 = x;
    h.below = false;
    return 3;
  }
  h.firstEntry = x;
  h.entered = true;
  p0 = x;
  return 2;
  // exercise: stub
  // return 2; // no clipping: the part below the horizon counts (negatively) too
  // exercise: end
}

// After the last edge: the piece along the horizon from the last exit back to the first entry,
// when the polygon entered before it first left (the loop started below the horizon).
int ltcClipClose(LtcHorizon h, out vec3 p0, out vec3 p1) {
  p0 = h.exitPoint;
  p1 = h.firstEntry;
  // exercise(ltc-close): begin
  // task: Return 2 (the piece h.exitPoint -> h.firstEntry, already in p0 and p1) when an exit is
  // task: still waiting (h.below) and the loop came back above before it (h.entered); else 0.
  return h.below && h.entered ? 2 : 0;
  // exercise: stub
  // return 0; // the polygon is left open along the horizon
  // exercise: end
}

// Adds the edge vectors of the polyline p0 -> p1 (-> p2) of `count` points.
void ltcAddPolyline(inout vec3 sum, int count, vec3 p0, vec3 p1, vec3 p2) {
  if (count >= 2) sum += ltcEdgeVector(ltcSafeNormalize(p0), ltcSafeNormalize(p1));
  if (count == 3) sum += ltcEdgeVector(ltcSafeNormalize(p1), ltcSafeNormalize(p2));
}

// The vector form factor of the polygon v[0..n-1] without clipping: its z component is the signed
// form factor when every vertex is above the horizon; its length and direction feed the sphere
// approximation of clipping (ltc.horizon=sphere).
vec3 ltcPolygonVector(vec3 v[kLtcMaxVertices], int n) {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < kLtcMaxVertices && i < n; ++i)
    sum += ltcEdgeVector(ltcSafeNormalize(v[i]), ltcSafeNormalize(v[i + 1 < n ? i + 1 : 0]));
  return sum;
}

// The vector form factor of the polygon v[0..n-1] clipped to the horizon z >= 0. Its z component
// is the signed form factor: positive when the vertices turn counter-clockwise about +z (the order
// ltcRectPolygon gives a light's emitting face seen from the front), negative for the opposite.
vec3 ltcClippedPolygonVector(vec3 v[kLtcMaxVertices], int n) {
  LtcHorizon h = ltcHorizonBegin();
  vec3 sum = vec3(0.0), p0, p1, p2;
  for (int i = 0; i < kLtcMaxVertices && i < n; ++i) {
    int count = ltcClipEdge(h, v[i], v[i + 1 < n ? i + 1 : 0], p0, p1, p2);
    ltcAddPolyline(sum, count, p0, p1, p2);
  }
  int count = ltcClipClose(h, p0, p1);
  ltcAddPolyline(sum, count, p0, p1, p1);
  return sum;
}

// Feeds the segment a->b of the surface-clipped polygon, taken through `inverse`, into the second
// clip (the LTC's horizon) and adds what is left of it.
void ltcLobeSegment(inout LtcHorizon lobe, inout vec3 sum, mat3 inverse, vec3 a, vec3 b) {
  vec3 q0, q1, q2;
  int count = ltcClipEdge(lobe, inverse * a, inverse * b, q0, q1, q2);
  ltcAddPolyline(sum, count, q0, q1, q2);
}

void ltcLobePolyline(inout LtcHorizon lobe, inout vec3 sum, mat3 inverse, int count, vec3 p0, vec3 p1, vec3 p2) {
  if (count >= 2) ltcLobeSegment(lobe, sum, inverse, p0, p1);
  if (count == 3) ltcLobeSegment(lobe, sum, inverse, p1, p2);
}

// The polygon v[0..n-1] clipped to the horizon z >= 0, taken through `inverse` (M^-1) and clipped
// again to the horizon there: the vector form factor of the clamped cosine over the part of the
// polygon that is above both the surface's horizon and the LTC's (techniques/ltc/README.md).
vec3 ltcDoublyClippedVector(vec3 v[kLtcMaxVertices], int n, mat3 inverse) {
  LtcHorizon surface = ltcHorizonBegin(), lobe = ltcHorizonBegin();
  vec3 sum = vec3(0.0), p0, p1, p2;
  for (int i = 0; i < kLtcMaxVertices && i < n; ++i) {
    int count = ltcClipEdge(surface, v[i], v[i + 1 < n ? i + 1 : 0], p0, p1, p2);
    ltcLobePolyline(lobe, sum, inverse, count, p0, p1, p2);
  }
  int count = ltcClipClose(surface, p0, p1);
  ltcLobePolyline(lobe, sum, inverse, count, p0, p1, p1);
  count = ltcClipClose(lobe, p0, p1);
  ltcAddPolyline(sum, count, p0, p1, p1);
  return sum;
}
