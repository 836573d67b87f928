// Tone curves and the sRGB transfer function.
vec3 toneAces(vec3 x) {
  // Narkowicz 2015, "ACES Filmic Tone Mapping Curve" (fit of the ACES RRT+ODT).
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

vec3 toneReinhard(vec3 x) { return x / (1.0 + x); }

vec3 linearToSrgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
