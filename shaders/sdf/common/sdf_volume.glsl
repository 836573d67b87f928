// The scene's signed distance volume (techniques/common/sdf/sdf_volume.h): a 3D texture of cubic
// voxels over the padded bounds, sampled trilinearly. Uniforms set by SdfTexture::bind.
uniform sampler3D uSdf;
uniform vec3 uSdfOrigin;    // min corner of the box the voxels tile (world)
uniform vec3 uSdfSize;      // its extent (world)
uniform float uSdfPadding;  // every triangle is at least this far inside the box

// Signed distance at x (scene units). Outside the box a lower bound: no geometry lies within the
// padding of the box, so the distance to the box plus the padding never oversteps.
float sdfDistance(vec3 x) {
  vec3 local = x - uSdfOrigin;
  vec3 inside = clamp(local, vec3(0.0), uSdfSize);
  float outside = length(local - inside);
  if (outside > 0.0) return outside + uSdfPadding;
  return texture(uSdf, local / uSdfSize).r;
}

// Where the ray o + t*d (d unit) leaves the box; 0 when it never is inside for t > 0.
float sdfBoxExit(vec3 o, vec3 d) {
  // A zero component would give 0 * inf = NaN on a slab plane: a tiny one bounds nothing instead.
  vec3 safe = vec3(abs(d.x) < 1e-30 ? 1e-30 : d.x, abs(d.y) < 1e-30 ? 1e-30 : d.y, abs(d.z) < 1e-30 ? 1e-30 : d.z);
  vec3 inv = 1.0 / safe;
  vec3 a = (uSdfOrigin - o) * inv, b = (uSdfOrigin + uSdfSize - o) * inv;
  vec3 far = max(a, b);
  vec3 near = min(a, b);
  float tFar = min(far.x, min(far.y, far.z));
  float tNear = max(near.x, max(near.y, near.z));
  return tFar >= max(tNear, 0.0) ? tFar : 0.0;
}
