#version 450
// Evaluates the two blocker estimates of shaders/shadow/common/moments.glsl on given moment
// vectors (tests/render/test_msm.cpp): per case (b1..b4, t), writes (found, zOcc) of the
// four-moment search (bias uMomentBias) and of the two-moment one (variance floor 1e-7).
layout(local_size_x = 1) in;
uniform float uMapResolution; // moments.glsl's box lookups need it; unused here
#include "shadow/common/moments.glsl"
layout(std430, binding = 0) readonly buffer Cases { vec4 cases[]; }; // per case: moments, then (t, 0, 0, 0)
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; }; // (found4, zOcc4, found2, zOcc2)
uniform float uMomentBias;

void main() {
  uint i = gl_GlobalInvocationID.x;
  vec4 moments = cases[2u * i];
  float t = cases[2u * i + 1u].x;
  float z4, z2;
  bool f4 = momentBlockerDepth4(moments, t, uMomentBias, z4);
  bool f2 = momentBlockerDepth(moments.xy, t, 1e-7, z2);
  results[i] = vec4(f4 ? 1.0 : 0.0, z4, f2 ? 1.0 : 0.0, z2);
}
