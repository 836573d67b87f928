// The weight of weighted blended order-independent transparency (McGuire & Bavoil 2013; docs/
// contract.md "Transparency"; techniques/wboit/README.md): w = a * f, a the fragment's coverage α
// (colour-weighted for color9), f a depth factor that makes nearer fragments count more. The view
// depth viewZ is GL view space z, negative in front of the camera: every use takes |z|, so pow()
// never sees a negative base (undefined in GLSL, NaN on most drivers).
const int kWeightEq7 = 0;
const int kWeightEq8 = 1;
const int kWeightEq9 = 2;
const int kWeightEq10 = 3;
const int kWeightColor9 = 4;

uniform int uWeightFunction; // wboit.weight: kWeightEq7 .. kWeightColor9
uniform float uDepthScale;   // wboit.depth_scale: the 200 of eq. 9 (eq9 and color9)
uniform float uExponent;     // wboit.exponent: the 4 of eq. 9 (eq9 and color9)
uniform float uMinWeight;    // wboit.min_weight: the paper's 1e-2
uniform float uMaxWeight;    // wboit.max_weight: the paper's 3e3

// w for a fragment of radiance c (not premultiplied) and coverage alpha at view-space z viewZ and
// window depth windowDepth (gl_FragCoord.z, in [0, 1]).
float wboitWeight(vec3 c, float alpha, float viewZ, float windowDepth) {
  // exercise(wboit-weight): begin
  // task: The weight w = a * f (McGuire & Bavoil 2013, eqs. 7-10). z = |viewZ| (viewZ is negative
  // task: in front of the camera; pow of a negative base is undefined). The depth factor f, before
  // task: the clamp: eq7 (kWeightEq7): 10 / (1e-5 + (z/5)^2 + (z/200)^6); eq8: 10 / (1e-5 +
  // task: (z/10)^3 + (z/200)^6); eq9 and color9: 0.03 / (1e-5 + (z/uDepthScale)^uExponent); eq10:
  // task: 3e3 * (1 - windowDepth)^3. Then f = clamp(f, uMinWeight, uMaxWeight) for every equation.
  // task: a = alpha, except color9: a = max(min(1, max(c.r, c.g, c.b) * alpha), alpha).
  // task: Return a * f. Write the integer powers as products (t * t), uExponent with pow().
  float z = abs(viewZ);
  float f;
  if (uWeightFunction == kWeightEq7) {
    float near = z / 5.0, far = z / 200.0, far3 = far * far * far;
    f = 10.0 / (1e-5 + near * near + far3 * far3);
  } else if (uWeightFunction == kWeightEq8) {
    float near = z / 10.0, far = z / 200.0, far3 = far * far * far;
    f = 10.0 / (1e-5 + near * near * near + far3 * far3);
  } else if (uWeightFunction == kWeightEq10) {
    float d = 1.0 - windowDepth;
    f = 3e3 * d * d * d;
  } else {
    f = 0.03 / (1e-5 + pow(z / uDepthScale, uExponent));
  }
  f = clamp(f, uMinWeight, uMaxWeight);
  float a = alpha;
  if (uWeightFunction == kWeightColor9) a = max(min(1.0, max(max(c.r, c.g), c.b) * alpha), alpha);
  return a * f;
  // exercise: stub
  // return alpha; // every depth weighs the same: the plain weighted average
  // exercise: end
}
