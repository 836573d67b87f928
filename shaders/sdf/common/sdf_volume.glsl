// The scene's signed distance volumes (techniques/common/sdf/sdf_texture.h): one (over the padded
// bounds of all opaque geometry) or one per opaque instance (over its own padded bounds), packed
// side by side in one 3D texture of cubic voxels, sampled trilinearly. Uniforms set by
// SdfTexture::bind; SDF_MAX_VOLUMES is defined by the technique from SdfTexture::kMaxVolumes.
#ifndef SDF_MAX_VOLUMES
#error "SDF_MAX_VOLUMES must be defined (SdfTexture::kMaxVolumes)"
#endif
uniform sampler3D uSdf;
uniform int uSdfCount;                      // volumes in use, 1..SDF_MAX_VOLUMES
uniform vec4 uSdfBox[SDF_MAX_VOLUMES];      // xyz: min corner of the box a volume's voxels tile; w: its padding
uniform vec4 uSdfExtent[SDF_MAX_VOLUMES];   // xyz: the box's extent; w: the voxel's edge
uniform vec4 uSdfTexel[SDF_MAX_VOLUMES];    // xyz: the volume's first texel in uSdf
uniform vec3 uSdfOrigin;    // the union of the boxes: min corner (world)
uniform vec3 uSdfSize;      // and extent; nothing lies outside it
uniform float uSdfVoxel;    // the finest volume's voxel edge (the slice view's bands)

// Signed distance at x (scene units): the minimum over the volumes of, outside a volume's box, a
// lower bound (no geometry of that volume lies within its padding of the box, so the distance to
// the box plus the padding never oversteps), inside it the trilinear sample. The sample's
// coordinate is kept half a texel inside the volume's own texels, so no neighbour in the texture
// blends in (the edge voxels' values, as clamp-to-edge gives a single volume).
float sdfDistance(vec3 x) {
  float h = 3.0e38;
  for (int v = 0; v < SDF_MAX_VOLUMES && v < uSdfCount; ++v) {
    vec3 local = x - uSdfBox[v].xyz;
    vec3 size = uSdfExtent[v].xyz;
    float outside = length(local - clamp(local, vec3(0.0), size));
    if (outside > 0.0) {
      h = min(h, outside + uSdfBox[v].w);
    } else {
      float voxel = uSdfExtent[v].w;
      vec3 texel = clamp(local / voxel, vec3(0.5), round(size / voxel) - 0.5);
      h = min(h, texture(uSdf, (uSdfTexel[v].xyz + texel) / vec3(textureSize(uSdf, 0))).r);
    }
  }
  return h;
}

// Where the ray o + t*d (d unit) leaves the union box; 0 when it never is inside for t > 0.
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
