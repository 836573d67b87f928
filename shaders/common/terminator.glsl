// The shading point of the shadow terminator rule (docs/measuring.md, "The shading point"):
// Hanika 2021, "Hacking the Shadow Terminator" (Ray Tracing Gems II, ch. 4). A point p of the flat
// triangle (p0, p1, p2) with barycentrics b is lifted onto the curved surface its vertex normals
// (unit, n0..n2) describe: for each vertex, p moved onto the vertex's tangent plane when it lies
// below it, and the three moves blended with b. Flat triangles (every normal equal to the face
// normal) and points above every tangent plane stay where they are. The CPU reference uses the same
// formula at ray hits (framework/reference/terminator.h).
vec3 terminatorPoint(vec3 p, vec3 b, vec3 p0, vec3 p1, vec3 p2, vec3 n0, vec3 n1, vec3 n2) {
  vec3 lift = max(vec3(dot(p0 - p, n0), dot(p1 - p, n1), dot(p2 - p, n2)), vec3(0.0));
  return p + (b.x * lift.x) * n0 + (b.y * lift.y) * n1 + (b.z * lift.z) * n2;
}
