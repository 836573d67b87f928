#version 450 core
// The general polygon path of shaders/ltc/polygon.glsl for tests/render/test_ltc_polygon.cpp: one
// invocation per polygon (3 to kLtcMaxVertices vertices, relative to the shading point, z up)
// writes its horizon-clipped signed form factor, the same through the doubly clipped path with
// M^-1 = I (the specular path's, which must agree), and the unclipped polygon's.
layout(local_size_x = 8) in;

#include "ltc/polygon.glsl"

struct Polygon {
  vec4 vertices[kLtcMaxVertices]; // xyz; w unused
  ivec4 count;                    // x the vertex count
};
layout(std430, binding = 0) readonly buffer Polygons { Polygon polygons[]; };
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; }; // x clipped, y doubly clipped, z unclipped

uniform int uCount;

void main() {
  int k = int(gl_GlobalInvocationID.x);
  if (k >= uCount) return;
  int n = clamp(polygons[k].count.x, 0, kLtcMaxVertices);
  vec3 v[kLtcMaxVertices];
  for (int i = 0; i < n; ++i) v[i] = polygons[k].vertices[i].xyz;
  results[k] = vec4(ltcClippedPolygonVector(v, n).z, ltcDoublyClippedVector(v, n, mat3(1.0)).z,
                    ltcPolygonVector(v, n).z, 0.0);
}
