// Box-filtered moments from a summed-area table, and the two reconstructions: Chebyshev's
// one-tailed bound on 2 moments (variance shadow maps) and the Hamburger 4-moment bound (moment
// shadow maps). Needs shadow_space.glsl (uMapResolution).
uniform usampler2D uSat;      // inclusive prefix sums of round((moments - uSatOffset) * uSatScale)
uniform vec4 uSatOffset;
uniform float uSatScale;      // fixed-point units per moment unit (a power of two)
uniform bool uSatWide;        // 64-bit sums: low words left, high words right (sat.comp, WIDE)

uvec4 satAt(ivec2 p) {
  if (p.x < 0 || p.y < 0) return uvec4(0u);
  return texelFetch(uSat, p, 0);
}
// The high words of a 64-bit table's sum at p (0 left of or below the map).
uvec4 satHighAt(ivec2 p) {
  if (p.x < 0 || p.y < 0) return uvec4(0u);
  return texelFetch(uSat, p + ivec2(int(uMapResolution), 0), 0);
}

// The texel box of half-width `radius` (texels) around uv, clipped to the map, at least one
// texel: its table corners (hi, and left of, below and diagonally below-left of lo) and area.
struct SatBox {
  ivec2 hi, c10, c01, c00;
  float area;
};
SatBox satBox(vec2 uv, float radius) {
  int size = int(uMapResolution);
  vec2 center = uv * uMapResolution;
  float r = max(radius, 0.5);
  ivec2 lo = clamp(ivec2(floor(center - r)), ivec2(0), ivec2(size - 1));
  ivec2 hi = clamp(ivec2(floor(center + r)), ivec2(0), ivec2(size - 1));
  hi = max(hi, lo);
  return SatBox(hi, ivec2(lo.x - 1, hi.y), ivec2(hi.x, lo.y - 1), lo - 1, float((hi.x - lo.x + 1) * (hi.y - lo.y + 1)));
}

// The box's sum from a 32-bit table: the four-corner difference wraps modulo 2^32 like the
// table's sums, so it is exact (sat.comp).
ivec4 narrowSum(SatBox b) { return ivec4(satAt(b.hi) - satAt(b.c10) - satAt(b.c01) + satAt(b.c00)); }

// The box's sum from a 64-bit table: the same on (low, high) word pairs, with borrows and carries.
void wideWords(SatBox b, out uvec4 low, out uvec4 high) {
  uvec4 borrow1, borrow2, carry;
  low = usubBorrow(satAt(b.hi), satAt(b.c10), borrow1);
  low = usubBorrow(low, satAt(b.c01), borrow2);
  low = uaddCarry(low, satAt(b.c00), carry);
  high = satHighAt(b.hi) - satHighAt(b.c10) - satHighAt(b.c01) + satHighAt(b.c00) - borrow1 - borrow2 + carry;
}
dvec4 wideSum(SatBox b) {
  uvec4 low, high;
  wideWords(b, low, high);
  return dvec4(ivec4(high)) * 4294967296.0LF + dvec4(low);
}

// Mean of the moments over the texel box of half-width `radius` (texels) around uv. The box's sum
// is exact; only its conversion to float rounds, relative to the box's own sum. What limits the
// moments is the 32-bit table's step 1/uSatScale (techniques/vssm/README.md, "Precision").
vec4 boxMoments(vec2 uv, float radius) {
  SatBox b = satBox(uv, radius);
  if (uSatWide) {
    // In float: the high word's float(int) * 2^32 plus float(low) rounds by at most a few hundred
    // units of 1/uSatScale (<= 2^-45), far below the moments' own float rounding.
    uvec4 low, high;
    wideWords(b, low, high);
    return (vec4(ivec4(high)) * 4294967296.0 + vec4(low)) / (b.area * uSatScale) + uSatOffset;
  }
  return vec4(narrowSum(b)) / (b.area * uSatScale) + uSatOffset;
}

// The same mean in double, from the exact sum (for msm's centred moments).
dvec4 boxMomentsExact(vec2 uv, float radius) {
  SatBox b = satBox(uv, radius);
  dvec4 sum = uSatWide ? wideSum(b) : dvec4(narrowSum(b));
  return sum / (double(b.area) * double(uSatScale)) + dvec4(uSatOffset);
}

// Inverse of the optimized quantization of 4 moments (Peters & Klein 2015, section 4.3; the
// forward transform is in shaders/shadow/moments.frag): (z, z^2, z^3, z^4) from the transformed
// ones, in double, or in float as before issue 19. Affine, so it also restores a box mean of
// transformed moments.
const dmat4 kRestoreOptimized = dmat4(0.2227744146LF, 0.1549679261LF, 0.1451988946LF, 0.163127443LF,
                                      0.0771972861LF, 0.1394629426LF, 0.2120202157LF, 0.2591432266LF,
                                      0.7926986636LF, 0.7963415838LF, 0.7258694464LF, 0.6539092497LF,
                                      0.0319417555LF, -0.1722823173LF, -0.2758014811LF, -0.3376131734LF);
dvec4 restoreOptimizedMoments(dvec4 m) {
  m.x -= 0.035955884801LF;
  return kRestoreOptimized * m;
}
vec4 restoreOptimizedMoments(vec4 m) {
  m.x -= 0.035955884801;
  return mat4(kRestoreOptimized) * m;
}

// The moments (E[z], .., E[z^4]) about t, E[(z - t)^k], in double, cast to float: the input of
// hamburger4Msm(about, 0.0, 0.0) for msm's centred moments (`msm.centred`;
// techniques/msm/README.md, "Precision"). The moment bias is applied first, as hamburger4Msm
// applies it: the result is the same bound in exact arithmetic, but a box of one depth near t then
// has small, well-scaled moments instead of b2 - b1^2 cancelling to a few float steps.
vec4 momentsAbout(dvec4 m, float t, float momentBias) {
  dvec4 b = mix(m, dvec4(0.5), double(momentBias));
  double s = double(t), s2 = s * s;
  return vec4(b.x - s, b.y - 2.0 * s * b.x + s2, b.z - 3.0 * s * b.y + 3.0 * s2 * b.x - s2 * s,
              b.w - 4.0 * s * b.z + 6.0 * s2 * b.y - 4.0 * s2 * s * b.x + s2 * s2);
}

// P(depth >= t) <= sigma^2 / (sigma^2 + (t - mu)^2) for t > mu (Chebyshev); 1 otherwise.
float chebyshevUpperBound(vec2 m, float t, float minVariance) {
  // exercise(vssm-chebyshev): begin
  // task: Chebyshev's one-tailed bound (Donnelly & Lauritzen 2006). m = (mu, E[z^2]): the mean
  // task: depth and the mean squared depth over a box of the map; t: the receiver's depth. The
  // task: variance is sigma^2 = max(E[z^2] - mu^2, minVariance) (the floor keeps planar receivers
  // task: from acne). Return 1.0 when t <= mu (the receiver is in front of the mean: unoccluded);
  // task: otherwise the upper bound of the unoccluded fraction P(z >= t) <= p_max =
  // task: sigma^2 / (sigma^2 + (t - mu)^2).
  float variance = max(m.y - m.x * m.x, minVariance);
  if (t <= m.x) return 1.0;
  float d = t - m.x;
  return variance / (variance + d * d);
  // exercise: stub
  // return 1.0; // unoccluded: every receiver is lit
  // exercise: end
}

// Mean blocker depth over a box with moments m = (mu, E[z^2]) (Yang et al. 2010, as VSSM and MSM
// estimate it): false when the box holds no blocker for a receiver at t (lit).
bool momentBlockerDepth(vec2 m, float t, float minVariance, out float zOcc) {
  // exercise(vssm-blocker): begin
  // task: Blocker estimate (Yang et al. 2010). p = chebyshevUpperBound(m, t, minVariance) is the
  // task: unoccluded fraction of the box. When p >= 0.99 (this includes t <= mu) the box holds no
  // task: blocker: return false (lit; zOcc is not used then; never divide by 1 - p ~ 0). Otherwise
  // task: split the mean depth into unoccluded texels, assumed at the receiver's depth t, and
  // task: blockers: mu = p * t + (1 - p) * zOcc, so set zOcc = (mu - p * t) / (1 - p), clamped to
  // task: [0, t], and return true. mu = m.x; depths are normalized linear light depths in [0,1].
  zOcc = t;
  float p = chebyshevUpperBound(m, t, minVariance);
  if (p >= 0.99) return false;
  zOcc = clamp((m.x - p * t) / (1.0 - p), 0.0, t);
  return true;
  // exercise: stub
  // zOcc = t;
  // return false; // no blocker found: every receiver is lit
  // exercise: end
}

// Reduces light bleeding by cutting off the lowest `amount` of the bound (Lauritzen 2007).
float reduceBleeding(float p, float amount) { return clamp((p - amount) / (1.0 - amount), 0.0, 1.0); }

// Hamburger 4MSM (Peters & Klein 2015, section 3 / algorithm 2): the fraction of the filtered
// depth distribution in front of t, as bounded by the three-point distribution with support
// {t, z2, z3} that matches the biased moments b. Returns the shadow intensity in [0,1].
float hamburger4Msm(vec4 moments, float t, float momentBias) {
  // exercise(msm-hamburger): begin
  // task: Hamburger 4MSM (Peters & Klein 2015, algorithm 2). moments = (b1, b2, b3, b4): the box
  // task: means of z, z^2, z^3, z^4; t: the receiver's depth. Return the shadow intensity in [0,1]
  // task: (the code below uses 1 - it as the visibility).
  // task: 1. Bias: b = mix(moments, vec4(0.5), momentBias) keeps the Hankel matrix invertible.
  // task: 2. Solve B c = (1, t, t^2) with B = [[1, b1, b2], [b1, b2, b3], [b2, b3, b4]], by its
  // task:    Cholesky factorization B = L D L^T: d22 = b2 - b1^2, l32 = (b3 - b1 b2) / d22,
  // task:    d33 = b4 - b2^2 - l32 (b3 - b1 b2), L = [[1, 0, 0], [b1, 1, 0], [b2, l32, 1]],
  // task:    D = diag(1, d22, d33); then forward substitution (L y = (1, t, t^2)), division by D
  // task:    and back substitution (L^T c = D^-1 y).
  // task:    Use these steps, not inverse(B): B is nearly singular, and a general 3x3 inverse in
  // task:    32-bit floats loses the digits the bound needs (measured: it fails 3 of 5 test views).
  // task: 3. The roots z2 <= z3 of c1 + c2 z + c3 z^2: with p = c2 / c3, q = c1 / c3,
  // task:    r = sqrt(max(p^2 / 4 - q, 0)): z2 = -p/2 - r, z3 = -p/2 + r.
  // task: 4. The three-point distribution on {t, z2, z3} with moments b: if z3 < t, both roots
  // task:    are in front: return 1 - wt, wt = (z2 z3 - b1 (z2 + z3) + b2) / ((t - z2)(t - z3));
  // task:    else if z2 < t, return w2 = (t z3 - b1 (t + z3) + b2) / ((z2 - t)(z2 - z3));
  // task:    else return 0.
  // task:    Clamp the returned weights to [0,1].
  vec4 b = mix(moments, vec4(0.5), momentBias);
  // Cholesky factorization of the Hankel matrix [[1,b1,b2],[b1,b2,b3],[b2,b3,b4]] (= L D L^T).
  float d22 = b.y - b.x * b.x;
  float l32d22 = b.z - b.x * b.y;
  float l32 = l32d22 / d22;
  float d33 = (b.w - b.y * b.y) - l32 * l32d22;
  // Solve B c = (1, t, t^2): forward substitution, scaling, back substitution.
  vec3 c = vec3(1.0, t, t * t);
  c.y -= b.x;
  c.z -= b.y + l32 * c.y;
  c.y /= d22;
  c.z /= d33;
  c.y -= l32 * c.z;
  c.x -= dot(c.yz, b.xy);
  // The other two support points are the roots of c.x + c.y z + c.z z^2.
  float p = c.y / c.z;
  float q = c.x / c.z;
  float r = sqrt(max(p * p * 0.25 - q, 0.0));
  float z2 = -0.5 * p - r;
  float z3 = -0.5 * p + r;
  if (z3 < t) {
    // Both roots in front: everything but the weight at t is in front.
    float wt = (z2 * z3 - b.x * (z2 + z3) + b.y) / ((t - z2) * (t - z3));
    return clamp(1.0 - wt, 0.0, 1.0);
  }
  if (z2 < t) {
    // Only z2 in front: its weight.
    float w2 = (t * z3 - b.x * (t + z3) + b.y) / ((z2 - t) * (z2 - z3));
    return clamp(w2, 0.0, 1.0);
  }
  return 0.0;
  // exercise: stub
  // return 0.0; // no shadow: every receiver is lit
  // exercise: end
}

// Mean blocker depth over a box from its four moments (Peters, Münstermann, Wetzstein & Klein
// 2016, moment soft shadow mapping; techniques/msm/README.md, "Four-moment blocker search"). The
// three-point distribution on {t, z2, z3} that matches the biased moments (as in hamburger4Msm)
// splits the box into the part at or behind t (lit) and the blockers strictly in front of t: their
// mass G and first moment M give zOcc = M / G. Both roots in front: G = 1 - w_t and M = b1 - w_t t
// (Yang et al.'s split with the four-moment weight w_t in place of Chebyshev's p); only z2 in
// front: G = w2 and zOcc = z2; none in front: no blocker. False (lit) when G < 0.01, as
// momentBlockerDepth's p >= 0.99. Every division is guarded (README, "Numerical guards").
bool momentBlockerDepth4(vec4 moments, float t, float momentBias, out float zOcc) {
  zOcc = t;
  // The bias towards b_ref of hamburger4Msm (spelled out: the exercise's mutations find that line).
  vec4 b = mix(moments, vec4(0.5, 0.5, 0.5, 0.5), momentBias);
  // The solve repeats hamburger4Msm's on purpose: that function is the msm exercise's region, which
  // students rewrite and stub, and the search must not depend on their version of it.
  // Cholesky factorization of the Hankel matrix, with floors on both pivots: in exact arithmetic
  // the bias keeps them positive (d22 >= momentBias / 4), in 32-bit floats they can round to 0 or
  // below at the smallest bias.
  float d22 = max(b.y - b.x * b.x, 1e-12);
  float l32d22 = b.z - b.x * b.y;
  float l32 = l32d22 / d22;
  float d33 = (b.w - b.y * b.y) - l32 * l32d22;
  if (d33 <= 1e-12) {
    // The biased moments hold at most two depths (one depth at 0 or 1, or the largest bias on one
    // depth): the Hankel matrix is singular, and the quadratic's coefficients below would be
    // rounding noise divided by the floor, so their roots, and whether a blocker is found, would
    // depend on the driver's float rounding (NVIDIA and llvmpipe disagreed). The two-moment
    // estimate on the same biased moments, spelled out as above, is stable there.
    float variance = max(b.y - b.x * b.x, 1e-12);
    if (t <= b.x) return false;
    float unoccluded = variance / (variance + (t - b.x) * (t - b.x));
    if (unoccluded >= 0.99) return false;
    zOcc = clamp((b.x - unoccluded * t) / (1.0 - unoccluded), 0.0, t);
    return true;
  }
  vec3 c = vec3(1.0, t, t * t);
  c.y -= b.x;
  c.z -= b.y + l32 * c.y;
  c.y /= d22;
  c.z /= d33;
  c.y -= l32 * c.z;
  c.x -= dot(c.yz, b.xy);
  // c3 -> 0 (the quadratic degenerates): keep its sign, bound its size, so p and q stay finite.
  float c3 = abs(c.z) < 1e-12 ? (c.z < 0.0 ? -1e-12 : 1e-12) : c.z;
  float p = c.y / c3;
  float q = c.x / c3;
  float r = sqrt(max(p * p * 0.25 - q, 0.0));
  float z2 = -0.5 * p - r;
  float z3 = -0.5 * p + r;
  float blockers;
  if (z3 < t) {
    // Both roots in front: all but the weight at t blocks. (t - z2)(t - z3) > 0, floored.
    float wt = clamp((z2 * z3 - b.x * (z2 + z3) + b.y) / max((t - z2) * (t - z3), 1e-20), 0.0, 1.0);
    blockers = 1.0 - wt;
    if (blockers < 0.01) return false;
    zOcc = clamp((b.x - wt * t) / blockers, 0.0, t);
    return true;
  }
  if (z2 < t) {
    // Only z2 in front: its weight is the blockers' mass, z2 their depth. (z2 - t)(z2 - z3) > 0.
    blockers = clamp((t * z3 - b.x * (t + z3) + b.y) / max((z2 - t) * (z2 - z3), 1e-20), 0.0, 1.0);
    if (blockers < 0.01) return false;
    zOcc = clamp(z2, 0.0, t);
    return true;
  }
  return false;
}
