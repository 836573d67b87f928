#version 450 core
// Reads the GPU scene data back for tests/render/test_scene_data.cpp: one invocation per triangle
// writes the corner indices and material word it read, its area and the sum of its corner
// normals, counts itself, and folds its corners into the bounds with atomicMin/atomicMax on
// order-preserving integer codes of the coordinates (no float atomics in core GL).
layout(local_size_x = 64) in;

#include "common/scene_triangles.glsl"

struct TriangleResult {
  uvec4 corners;   // xyz the vertex indices, w the material word
  vec4 normalArea; // xyz the sum of the three corner normals, w the area
};
layout(std430, binding = 0) buffer Results {
  uint visited;        // triangles visited
  uint infoTriangles;  // the info block's counts as read
  uint infoVertices;
  uint pad;
  int codeMin[4];      // [0..2] order-preserving codes of the corners' minimum per axis
  int codeMax[4];
  vec4 infoMin;        // the info block's bounds as read
  vec4 infoMax;
  TriangleResult results[];
};

// Signed-integer order equals float order: positive floats keep their bits, negative ones flip
// all bits but the sign.
int orderCode(float f) {
  int bits = floatBitsToInt(f);
  return bits >= 0 ? bits : bits ^ 0x7FFFFFFF;
}

void main() {
  uint t = gl_GlobalInvocationID.x;
  if (t == 0u) {
    infoTriangles = sceneTriangleCount;
    infoVertices = sceneVertexCount;
    infoMin = sceneBoundsMin;
    infoMax = sceneBoundsMax;
  }
  if (t >= sceneTriangleCount) return;
  vec3 a, b, c;
  sceneTriangleCorners(t, a, b, c);
  uvec4 tri = sceneTriangles[t];
  vec3 normalSum = sceneNormals[tri.x].xyz + sceneNormals[tri.y].xyz + sceneNormals[tri.z].xyz;
  uint word = sceneTriangleMaterial(t) | (sceneTriangleTransparent(t) ? SCENE_TRANSPARENT : 0u);
  results[t].corners = uvec4(tri.xyz, word);
  results[t].normalArea = vec4(normalSum, 0.5 * length(cross(b - a, c - a)));
  atomicAdd(visited, 1u);
  for (int axis = 0; axis < 3; ++axis) {
    float lo = min(a[axis], min(b[axis], c[axis])), hi = max(a[axis], max(b[axis], c[axis]));
    atomicMin(codeMin[axis], orderCode(lo));
    atomicMax(codeMax[axis], orderCode(hi));
  }
}
