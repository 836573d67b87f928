// The mip method's filters (Jimenez 2014, "Next Generation Post Processing in Call of Duty:
// Advanced Warfare"): a 13-tap downsample and a 3x3 tent upsample, each made of bilinear taps of a
// texture with linear filtering and a black border (outside the frame is black). Offsets are in
// texels of the texture sampled; techniques/bloom/README.md derives the blur each one adds.
const vec3 kFilterLuma = vec3(0.2126, 0.7152, 0.0722);

// Karis's weight of a group of texels: 1 / (1 + luma).
float karisWeight(vec3 c) { return 1.0 / (1.0 + dot(c, kFilterLuma)); }

// The level below `src` at `uv`, the centre of a destination texel (a corner shared by four source
// texels); `texel` = 1 / the size of src; `karis`: weight each 2x2 group by karisWeight.
vec3 bloomDownsample(sampler2D src, vec2 uv, vec2 texel, bool karis) {
  // exercise(bloom-downsample): begin
  // task: The 13-tap downsample. Take 13 bilinear taps texture(src, uv + texel * o).rgb at the
  // task: offsets o = (-2,2) (0,2) (2,2) (-2,0) (0,0) (2,0) (-2,-2) (0,-2) (2,-2) (outer grid,
  // task: each tap the mean of 2x2 texels) and (-1,1) (1,1) (-1,-1) (1,-1) (inner square).
  // task: Form five 2x2-tap groups, each the mean of its four taps: the inner square, and the
  // task: four corner squares of the outer grid (top-left: (-2,2) (0,2) (-2,0) (0,0), and so on).
  // task: Without karis return 0.5 * inner + 0.125 * (sum of the four corner groups).
  // task: With karis weight each group g additionally by karisWeight(g) and divide by the sum of
  // task: the weights: (0.5 w_i inner + 0.125 sum w_c corner) / (0.5 w_i + 0.125 sum w_c).
  vec3 a = texture(src, uv + texel * vec2(-2.0, 2.0)).rgb;
  vec3 b = texture(src, uv + texel * vec2(0.0, 2.0)).rgb;
  vec3 c = texture(src, uv + texel * vec2(2.0, 2.0)).rgb;
  vec3 d = texture(src, uv + texel * vec2(-2.0, 0.0)).rgb;
  vec3 e = texture(src, uv).rgb;
  vec3 f = texture(src, uv + texel * vec2(2.0, 0.0)).rgb;
  vec3 g = texture(src, uv + texel * vec2(-2.0, -2.0)).rgb;
  vec3 h = texture(src, uv + texel * vec2(0.0, -2.0)).rgb;
  vec3 i = texture(src, uv + texel * vec2(2.0, -2.0)).rgb;
  vec3 j = texture(src, uv + texel * vec2(-1.0, 1.0)).rgb;
  vec3 k = texture(src, uv + texel * vec2(1.0, 1.0)).rgb;
  vec3 l = texture(src, uv + texel * vec2(-1.0, -1.0)).rgb;
  vec3 m = texture(src, uv + texel * vec2(1.0, -1.0)).rgb;
  vec3 inner = (j + k + l + m) * 0.25;
  vec3 topLeft = (a + b + d + e) * 0.25;
  vec3 topRight = (b + c + e + f) * 0.25;
  vec3 bottomLeft = (d + e + g + h) * 0.25;
  vec3 bottomRight = (e + f + h + i) * 0.25;
  if (!karis) return 0.5 * inner + 0.125 * (topLeft + topRight + bottomLeft + bottomRight);
  float wi = 0.5 * karisWeight(inner);
  float w0 = 0.125 * karisWeight(topLeft), w1 = 0.125 * karisWeight(topRight);
  float w2 = 0.125 * karisWeight(bottomLeft), w3 = 0.125 * karisWeight(bottomRight);
  return (wi * inner + w0 * topLeft + w1 * topRight + w2 * bottomLeft + w3 * bottomRight) / (wi + w0 + w1 + w2 + w3);
  // exercise: stub
  // return texture(src, uv).rgb; // a 2x2 box: blurs too little, and aliases
  // exercise: end
}

// `src` (one level coarser) at `uv` of the finer level, through a 3x3 tent of bilinear taps one
// source texel apart; `texel` = 1 / the size of src.
vec3 bloomUpsample(sampler2D src, vec2 uv, vec2 texel) {
  // exercise(bloom-upsample): begin
  // task: The 3x3 tent upsample: nine bilinear taps texture(src, uv + texel * vec2(x, y)).rgb for
  // task: x, y in {-1, 0, 1}, weighted (1 2 1) x (1 2 1) / 16: 4/16 at the centre, 2/16 at the four
  // task: edge taps, 1/16 at the four corners. The weights sum to 1 (energy is kept).
  vec3 sum = 4.0 * texture(src, uv).rgb;
  sum += 2.0 * (texture(src, uv + texel * vec2(-1.0, 0.0)).rgb + texture(src, uv + texel * vec2(1.0, 0.0)).rgb +
                texture(src, uv + texel * vec2(0.0, -1.0)).rgb + texture(src, uv + texel * vec2(0.0, 1.0)).rgb);
  sum += texture(src, uv + texel * vec2(-1.0, -1.0)).rgb + texture(src, uv + texel * vec2(1.0, -1.0)).rgb +
         texture(src, uv + texel * vec2(-1.0, 1.0)).rgb + texture(src, uv + texel * vec2(1.0, 1.0)).rgb;
  return sum / 16.0;
  // exercise: stub
  // return texture(src, uv).rgb; // bilinear only: the coarse levels show as blocks
  // exercise: end
}
