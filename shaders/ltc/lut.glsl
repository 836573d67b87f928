// The LTC tables (assets/ltc/README.md) and the transform of a light's vertices into the cosine's
// frame (techniques/ltc/README.md "The lookup"). The tables are N x N textures with linear
// filtering: texel (i, j) holds the cell of perceptual roughness i/(N-1) and sqrt(1 - cos theta_v)
// = j/(N-1).
uniform sampler2D uLtcMatrix;  // (a, b, c, d): M^-1 = [[a, 0, b], [0, 1, 0], [c, 0, d]] (rows)
uniform sampler2D uLtcScale;   // (magnitude, fresnel, diffuse_fresnel, fit error)
uniform float uLtcSize;        // N, the textures' size (ltc.table_size)

// Texture coordinate of the cell (roughness, cosThetaV): the grid's end points are texel centres.
vec2 ltcLutUv(float roughness, float cosThetaV) {
  // exercise(ltc-lut_uv): begin
  // task: Return the texture coordinate of the table cell for perceptual roughness `roughness`
  // task: and cos theta_v = cosThetaV (both in [0, 1]): the table's axes are (roughness,
  // task: sqrt(1 - cos theta_v)), their 0 and 1 at the centres of the first and last texels of a
  // task: uLtcSize x uLtcSize texture: uv = axes * (N - 1) / N + 0.5 / N.
  vec2 axes = vec2(roughness, sqrt(1.0 - cosThetaV));
  return axes * ((uLtcSize - 1.0) / uLtcSize) + 0.5 / uLtcSize;
  // exercise: stub
  // return vec2(roughness, cosThetaV); // no half-texel offsets, cos theta_v taken linearly
  // exercise: end
}

// M^-1 from its four stored elements (a, b, c, d), as a GLSL (column-major) matrix.
mat3 ltcInverseMatrix(vec4 t) {
  return mat3(vec3(t.x, 0.0, t.z), vec3(0.0, 1.0, 0.0), vec3(t.y, 0.0, t.w));
}

// World to the LTC frame of (n, v): x toward v's part perpendicular to n, z = n. v parallel to n
// (no tangential part: the lobe is symmetric about n there) takes any x perpendicular to n.
mat3 ltcFrame(vec3 n, vec3 v) {
  // exercise(ltc-frame): begin
  // task: Return the matrix that takes world directions into the (t1, t2, n) frame: t1 the unit
  // task: vector along v's part perpendicular to n, t2 = cross(n, t1), so the frame's z is n and v
  // task: lies in its xz-plane with x >= 0. When v has no such part (|v - n (n.v)|^2 <= 1e-12), t1
  // task: is any unit vector perpendicular to n. GLSL matrices are column-major: transpose(mat3(
  // task: t1, t2, n)) has the rows t1, t2, n.
  vec3 t1 = v - n * dot(n, v);
  float l2 = dot(t1, t1);
  if (l2 > 1e-12) {
    t1 *= inversesqrt(l2);
  } else {
    t1 = normalize(abs(n.x) < 0.9 ? cross(n, vec3(1.0, 0.0, 0.0)) : cross(n, vec3(0.0, 1.0, 0.0)));
  }
  vec3 t2 = cross(n, t1);
  return transpose(mat3(t1, t2, n));
  // exercise: stub
  // return mat3(1.0); // world axes: the lobe is not turned with the surface
  // exercise: end
}
