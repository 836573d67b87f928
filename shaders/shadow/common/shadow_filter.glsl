// Percentage-closer filtering over the shadow stage's map (Reeves et al. 1987): the fraction of
// depth comparisons that pass over a kernel of taps, never an average of depths. Needs
// shadow_space.glsl. Taps are points in the unit disk (uTaps), scaled to a radius in map texels,
// optionally rotated per pixel by a tileable blue-noise angle.
uniform vec2 uTaps[64];
uniform int uTapCount;
uniform sampler2D uRotationNoise;
uniform bool uRotateTaps;
uniform bool uReceiverPlaneBias;

const float kMaxReceiverPlaneBias = 0.01; // depth units: guard against derivatives across edges

mat2 tapRotation() {
  if (!uRotateTaps) return mat2(1.0);
  ivec2 size = textureSize(uRotationNoise, 0);
  float angle = texelFetch(uRotationNoise, ivec2(gl_FragCoord.xy) % size, 0).r * 6.28318531;
  float c = cos(angle), s = sin(angle);
  return mat2(c, s, -s, c);
}

#if SHADOW_PROJECTION == 2
// Two axes spanning the cube face that `dir` points into, and dir scaled so that face is at 1.
void cubeFaceFrame(vec3 dir, out vec3 onFace, out vec3 t1, out vec3 t2) {
  vec3 a = abs(dir);
  if (a.x >= a.y && a.x >= a.z) {
    onFace = dir / a.x; t1 = vec3(0, 1, 0); t2 = vec3(0, 0, 1);
  } else if (a.y >= a.z) {
    onFace = dir / a.y; t1 = vec3(1, 0, 0); t2 = vec3(0, 0, 1);
  } else {
    onFace = dir / a.z; t1 = vec3(1, 0, 0); t2 = vec3(0, 1, 0);
  }
}

float shadowFilter(vec3 q, float radiusTexels, int tapCount) {
  vec3 dir;
  float depth;
  if (!shadowCoordCube(q, dir, depth)) return 1.0;
  vec3 onFace, t1, t2;
  cubeFaceFrame(dir, onFace, t1, t2);
  float scale = radiusTexels * 2.0 / uMapResolution; // a face spans 2 units
  mat2 rotation = tapRotation();
  float lit = 0.0;
  for (int i = 0; i < tapCount; ++i) {
    vec2 o = rotation * uTaps[i] * scale;
    lit += texture(uShadowMap, vec4(onFace + o.x * t1 + o.y * t2, depth - uConstantBias));
  }
  return lit / float(tapCount);
}
#else
// Receiver-plane depth bias: the depth slope of the receiver in map space, from screen-space
// derivatives, so each tap compares against the receiver's own plane at its offset.
vec2 receiverPlaneSlope(vec3 coord) {
  vec3 dx = dFdx(coord), dy = dFdy(coord);
  mat2 j = mat2(dx.xy, dy.xy);
  float det = determinant(j);
  if (abs(det) < 1e-14) return vec2(0.0);
  return transpose(inverse(j)) * vec2(dx.z, dy.z);
}

float shadowFilter(vec3 q, float radiusTexels, int tapCount) {
  vec3 coord;
  bool inside = shadowCoord2D(q, coord);
  vec2 slope = uReceiverPlaneBias ? receiverPlaneSlope(coord) : vec2(0.0); // all lanes: derivatives
  if (!inside) return 1.0;
  // exercise(pcf-filter): begin
  // task: Percentage-closer filter (Reeves et al. 1987): average depth comparisons, never depths.
  // task: coord.xy is the receiver's map uv, coord.z its map depth. For each tap i < tapCount:
  // task: offset in uv o = rotation * uTaps[i] * radiusTexels / uMapResolution, with
  // task: rotation = tapRotation() (per-pixel blue-noise rotation, identity when off) and uTaps[i]
  // task: a point of the unit disk (rotation * uTaps[i], not uTaps[i] * rotation, which rotates the
  // task: other way: another noise pattern, graded as a difference); receiver-plane bias
  // task: planeBias = clamp(dot(slope, o), -kMaxReceiverPlaneBias, kMaxReceiverPlaneBias), with
  // task: slope the receiver's depth per uv (computed above; zero when that bias is off);
  // task: the tap passes (1) or not (0) by the hardware comparison
  // task: texture(uShadowMap, vec3(coord.xy + o, coord.z + planeBias - uConstantBias)).
  // task: Return the number of passing taps divided by tapCount (1 = lit, 0 = shadowed).
  float scale = radiusTexels / uMapResolution;
  mat2 rotation = tapRotation();
  float lit = 0.0;
  for (int i = 0; i < tapCount; ++i) {
    vec2 o = rotation * uTaps[i] * scale;
    float planeBias = clamp(dot(slope, o), -kMaxReceiverPlaneBias, kMaxReceiverPlaneBias);
    lit += texture(uShadowMap, vec3(coord.xy + o, coord.z + planeBias - uConstantBias));
  }
  return lit / float(tapCount);
  // exercise: stub
  // return 1.0; // lit: every tap passes
  // exercise: end
}
#endif
