// Procedural meshes for the built-in scenes, and the vertex-attribute generators shared with the
// glTF loader (flat normals, tangents, bounds).
//
// Conventions (glTF's): counter-clockwise front faces, outward unit normals, UV (0,0) at the top
// left of the image. Tangents point along +u; w is the handedness such that
// bitangent = cross(normal, tangent.xyz) * w points "up" in the image (towards decreasing v), which
// is the direction a normal map's green channel encodes.
#pragma once
#include "scene/scene.h"

#include <string>

namespace rtlab {

// A box of the given full size, centred at the origin; 24 vertices (hard edges).
Mesh makeBox(const std::string& name, const glm::vec3& size);

// A UV sphere centred at the origin; `slices` around the y axis, `stacks` from pole to pole.
Mesh makeSphere(const std::string& name, float radius, int slices = 48, int stacks = 24);

// A rectangle centred at `center` spanning center +- halfU +- halfV, facing
// normalize(cross(halfU, halfV)); u runs along +halfU, v along -halfV (image upright when halfV is
// "up"). `segments` subdivides each edge.
Mesh makeQuad(const std::string& name, const glm::vec3& center, const glm::vec3& halfU,
              const glm::vec3& halfV, int segments = 1);

// A horizontal plane at y = 0 facing +y, sizeX by sizeZ, centred at the origin.
Mesh makePlane(const std::string& name, float sizeX, float sizeZ, int segments = 1);

// A capped cylinder around the y axis from y = 0 to y = height.
Mesh makeCylinder(const std::string& name, float radius, float height, int segments = 48);

// Appends the quad of makeQuad to an existing mesh (for multi-face meshes).
void appendQuad(Mesh& mesh, const glm::vec3& center, const glm::vec3& halfU,
                const glm::vec3& halfV, int segments = 1);

// Recomputes Mesh::bounds from the vertices.
void computeBounds(Mesh& mesh);

// Replaces the normals with flat per-face normals (as glTF requires when NORMAL is missing). Every
// triangle gets its own three vertices, so the mesh is de-indexed. A degenerate triangle gets +y.
void generateFlatNormals(Mesh& mesh);

// Per-vertex tangents from the per-triangle UV derivatives (area-weighted sum over the triangles
// sharing a vertex), Gram-Schmidt orthogonalised against the normal, handedness in w. Vertices
// whose UVs give no direction get an arbitrary unit tangent perpendicular to the normal.
void generateTangents(Mesh& mesh);

// Makes normals unit length (zero or non-finite ones become +y) and tangents unit length and
// perpendicular to the normal with w = +-1. Returns how many vertices needed a replacement.
int normalizeFrames(Mesh& mesh);

// Any unit vector perpendicular to the unit vector n.
glm::vec3 anyPerpendicular(const glm::vec3& n);

} // namespace rtlab
