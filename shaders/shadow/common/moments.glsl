// Box-filtered moments from a summed-area table, and the two reconstructions: Chebyshev's
// one-tailed bound on 2 moments (variance shadow maps) and the Hamburger 4-moment bound (moment
// shadow maps). Needs shadow_space.glsl (uMapResolution).
uniform usampler2D uSat;      // inclusive prefix sums of round((moments - uSatOffset) * uSatScale)
uniform vec4 uSatOffset;
uniform float uSatScale;      // fixed-point units per moment unit (a power of two)

uvec4 satAt(ivec2 p) {
  if (p.x < 0 || p.y < 0) return uvec4(0u);
  return texelFetch(uSat, p, 0);
}

// Mean of the moments over the texel box of half-width `radius` (texels) around uv, clipped to
// the map. At least one texel. The four-corner difference wraps modulo 2^32 like the table's
// sums, so the box's sum is exact (sat.comp); only its conversion to float rounds, relative to
// the box's own sum.
vec4 boxMoments(vec2 uv, float radius) {
  int size = int(uMapResolution);
  vec2 center = uv * uMapResolution;
  float r = max(radius, 0.5);
  ivec2 lo = clamp(ivec2(floor(center - r)), ivec2(0), ivec2(size - 1));
  ivec2 hi = clamp(ivec2(floor(center + r)), ivec2(0), ivec2(size - 1));
  hi = max(hi, lo);
  uvec4 sum = satAt(hi) - satAt(ivec2(lo.x - 1, hi.y)) - satAt(ivec2(hi.x, lo.y - 1)) + satAt(lo - 1);
  float area = float((hi.x - lo.x + 1) * (hi.y - lo.y + 1));
  return vec4(ivec4(sum)) / (area * uSatScale) + uSatOffset;
}

// P(depth >= t) <= sigma^2 / (sigma^2 + (t - mu)^2) for t > mu (Chebyshev); 1 otherwise.
float chebyshevUpperBound(vec2 m, float t, float minVariance) {
  float variance = max(m.y - m.x * m.x, minVariance);
  if (t <= m.x) return 1.0;
  float d = t - m.x;
  return variance / (variance + d * d);
}

// Reduces light bleeding by cutting off the lowest `amount` of the bound (Lauritzen 2007).
float reduceBleeding(float p, float amount) { return clamp((p - amount) / (1.0 - amount), 0.0, 1.0); }

// Hamburger 4MSM (Peters & Klein 2015, section 3 / algorithm 2): the fraction of the filtered
// depth distribution in front of t, as bounded by the three-point distribution with support
// {t, z2, z3} that matches the biased moments b. Returns the shadow intensity in [0,1].
float hamburger4Msm(vec4 moments, float t, float momentBias) {
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
}
