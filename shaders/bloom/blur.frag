#version 450 core
// bloom.blur_x<k> / bloom.blur_y<k>: one direction of octave k's Gaussian at full resolution,
// exp(-i^2 / (2 sigma^2)) for |i| <= uTaps, times uScale (the truncated kernel's renormalisation,
// and 1/n on the second pass). Taps outside the frame read black and are skipped; uTaps never
// exceeds the frame's size, however wide the Gaussian.
uniform sampler2D uSource;
uniform ivec2 uDirection;
uniform float uSigma;
uniform int uTaps;
uniform float uScale;

layout(location = 0) out vec4 oColor;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  ivec2 size = textureSize(uSource, 0);
  float falloff = -0.5 / (uSigma * uSigma);
  vec3 sum = texelFetch(uSource, px, 0).rgb;
  for (int i = 1; i <= uTaps; ++i) {
    float w = exp(falloff * float(i * i));
    ivec2 a = px + i * uDirection, b = px - i * uDirection;
    if (all(lessThan(a, size))) sum += w * texelFetch(uSource, a, 0).rgb;
    if (all(greaterThanEqual(b, ivec2(0)))) sum += w * texelFetch(uSource, b, 0).rgb;
  }
  oColor = vec4(uScale * sum, 1.0);
}
