#version 450 core
// The moment techniques' lookups on their real table (tests/render/test_moment_model.cpp): per
// query (u, v, radius, t), boxMoments and the bound of shaders/shadow/common/moments.glsl, as the
// visibility shaders call them: MOMENTS 2, Chebyshev's bound (vssm, before the bleeding
// reduction); MOMENTS 4, 1 - the Hamburger 4MSM bound of the restored moments (msm), or of the
// moments about t restored in double (msm.centred).
layout(local_size_x = 64) in;
uniform float uMapResolution;
#include "shadow/common/moments.glsl"

layout(std430, binding = 0) readonly buffer Queries { vec4 queries[]; };
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; }; // 2 per query: moments, (visibility, 0, 0, 0)
uniform int uCount;
uniform float uKnob; // vssm: variance floor; msm: moment bias
uniform bool uCentred; // msm: the bound from the moments about t (msm.centred)

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= uCount) return;
  vec4 q = queries[i];
  vec4 m = boxMoments(q.xy, q.z);
#if MOMENTS == 2
  float visibility = chebyshevUpperBound(m.xy, q.w, uKnob);
#else
  dvec4 exact = restoreOptimizedMoments(boxMomentsExact(q.xy, q.z));
  m = uCentred ? vec4(exact) : restoreOptimizedMoments(m);
  float visibility = 1.0 - (uCentred ? hamburger4Msm(momentsAbout(exact, q.w, uKnob), 0.0, 0.0)
                                     : hamburger4Msm(m, q.w, uKnob));
#endif
  results[2 * i] = m;
  results[2 * i + 1] = vec4(visibility, 0.0, 0.0, 0.0);
}
