#version 450 core
// The general polygon path of shaders/ltc/polygon.glsl for tests/render/test_ltc_polygon.cpp: one
// invocation per polygon (3 to kLtcMaxVertices vertices, relative to the shading point, z up)
// writes its horizon-clipped signed form factor and the vertex count after clipping.
layout(local_size_x = 8) in;

#include "ltc/polygon.glsl"

struct Polygon {
  vec4 vertices[kLtcMaxVertices]; // xyz; w unused
  ivec4 count;                    // x the vertex count
};
layout(std430, binding = 0) readonly buffer Polygons { Polygon polygons[]; };
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; }; // x form factor, y clipped count

uniform int uCount;

void main() {
  int k = int(gl_GlobalInvocationID.x);
  if (k >= uCount) return;
  int n = clamp(polygons[k].count.x, 0, kLtcMaxVertices);
  vec3 v[kLtcMaxClipped];
  for (int i = 0; i < n; ++i) v[i] = polygons[k].vertices[i].xyz;
  float formFactor = ltcClippedFormFactor(v, n);
  int m = ltcClipToHorizon(v, n);
  results[k] = vec4(formFactor, float(m), 0.0, 0.0);
}
