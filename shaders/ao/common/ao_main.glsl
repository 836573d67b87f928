// main() of every ao estimator, included after the technique defines
//   float aoEvaluate(ivec2 px, AoSurface s)  // unoccluded fraction in [0, 1]
// Writes ao.raw (0 on sky pixels, which every later pass skips), or with AO_PATTERN the debug view
// <id>.pattern at frame resolution: the raw AO in grey, the pattern pixel's samples as squares
// (green unoccluded, red occluded), the pattern pixel itself in white.
#ifdef AO_PATTERN
layout(location = 0) out vec4 oValue;
#else
layout(location = 0) out float oAo;
#endif

void main() {
#ifdef AO_PATTERN
  ivec2 frag = ivec2(gl_FragCoord.xy);
  ivec2 px = min(frag / uScale, uAoSize - 1);
#else
  ivec2 px = ivec2(gl_FragCoord.xy);
#endif
  AoSurface s;
  bool surface = aoSurface(px, s);
  float ao = surface ? clamp(aoEvaluate(px, s), 0.0, 1.0) : 0.0;
#ifdef AO_PATTERN
  gPatternFrag = vec2(frag) + 0.5;
  gPatternMarker = max(1.0, float(uFullSize.y) / 240.0);
  vec3 color = vec3(0.6 * ao); // sky: overwritten below
  AoSurface c;
  if (aoSurface(uPatternPixel, c)) {
    gPatternActive = true;
    aoEvaluate(uPatternPixel, c);
    if (gPatternMark.a > 0.0) color = gPatternMark.rgb;
    vec2 d = abs(aoFullPixel(uPatternPixel) - gPatternFrag);
    if (max(d.x, d.y) <= gPatternMarker) color = vec3(1.0);
  }
  oValue = surface ? vec4(color, 1.0) : vec4(0.0); // background: 0, mask 0
#else
  oAo = ao;
#endif
}
