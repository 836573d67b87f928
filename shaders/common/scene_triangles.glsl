// The scene's triangles in world space for compute shaders (docs/scene-data.md "GPU scene data"),
// bound by SceneGpu::bindTriangles(first): first + 0 the info block, + 1 positions, + 2 normals,
// + 3 triangles. Define SCENE_TRIANGLES_BINDING (ProgramDesc::defines) to move them, and pass the
// same number to bindTriangles. Every array holds 16-byte elements (std430).
#ifndef SCENE_TRIANGLES_BINDING
#define SCENE_TRIANGLES_BINDING 4
#endif

layout(std430, binding = SCENE_TRIANGLES_BINDING) readonly buffer SceneTriangleInfo {
  vec4 sceneBoundsMin; // xyz: the vertices' world bounds; (0, 0, 0) for a scene without vertices
  vec4 sceneBoundsMax;
  uint sceneTriangleCount;
  uint sceneVertexCount;
};
layout(std430, binding = SCENE_TRIANGLES_BINDING + 1) readonly buffer ScenePositions {
  vec4 scenePositions[]; // xyz world position, w = 1
};
layout(std430, binding = SCENE_TRIANGLES_BINDING + 2) readonly buffer SceneNormals {
  vec4 sceneNormals[]; // xyz world unit normal (0 when degenerate), w = 0
};
layout(std430, binding = SCENE_TRIANGLES_BINDING + 3) readonly buffer SceneTriangles {
  uvec4 sceneTriangles[]; // xyz vertex indices, w = material (bits 0-23) | transparent (bit 31)
};

const uint SCENE_MATERIAL_MASK = 0x00FFFFFFu;
const uint SCENE_DEFAULT_MATERIAL = 0x00FFFFFFu; // the mesh has no material
const uint SCENE_TRANSPARENT = 0x80000000u;      // the instance is drawn by the transparency stage

// Index into Scene::materials, or SCENE_DEFAULT_MATERIAL.
uint sceneTriangleMaterial(uint t) { return sceneTriangles[t].w & SCENE_MATERIAL_MASK; }
bool sceneTriangleTransparent(uint t) { return (sceneTriangles[t].w & SCENE_TRANSPARENT) != 0u; }
// The corners of triangle t in world space.
void sceneTriangleCorners(uint t, out vec3 a, out vec3 b, out vec3 c) {
  uvec4 tri = sceneTriangles[t];
  a = scenePositions[tri.x].xyz;
  b = scenePositions[tri.y].xyz;
  c = scenePositions[tri.z].xyz;
}
