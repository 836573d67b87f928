// Tone curves and the sRGB transfer function.
// Narkowicz 2015, "ACES Filmic Tone Mapping Curve" (fit of the ACES RRT+ODT). The fit reaches 1 at
// x = 7.25 and stays above it, so x is first limited to 64: the output is unchanged, and the
// products stay below 2.51 * 64^2 = 10281 whatever the input (+inf included). In 32-bit floats (GLSL
// `float` on desktop GL) even 65504 * exposure 100 would be fine; in 16-bit floats the numerator
// x * (2.51 x + 0.03) overflows from x = 161.6 (docs/stages.md "The HDR clamp").
vec3 toneAces(vec3 x) {
  x = min(x, vec3(64.0));
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

vec3 toneReinhard(vec3 x) { return x / (1.0 + x); }

vec3 linearToSrgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
