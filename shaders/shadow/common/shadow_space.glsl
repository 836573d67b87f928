// Light-space lookups into the shadow stage's depth map ("shadow.depth"), shared by every
// depth-comparison technique. Needs SHADOW_PROJECTION: 0 orthographic, 1 perspective, 2 cube.
// Uniforms are set by bindShadowSpace() (techniques/common/shadow/shadow_depth.cpp).
uniform mat4 uLightViewProj;
uniform vec3 uLightPosition;
uniform vec3 uLightDirection;
uniform float uLightNear;
uniform float uLightFar;
uniform float uTexelScale;
uniform float uNormalBias;    // shadow-map texels
uniform float uConstantBias;  // depth units of the map, [0,1]
uniform float uMapResolution; // texels per side (per cube face)
#if SHADOW_PROJECTION == 2
uniform samplerCubeShadow uShadowMap;
#else
uniform sampler2DShadow uShadowMap;
#endif

// World size of one map texel at p.
float shadowTexelWorld(vec3 p) {
#if SHADOW_PROJECTION == 0
  return uTexelScale;
#elif SHADOW_PROJECTION == 1
  return uTexelScale * max(dot(p - uLightPosition, uLightDirection), 0.0);
#else
  vec3 v = abs(p - uLightPosition);
  return uTexelScale * max(v.x, max(v.y, v.z));
#endif
}

// True when the surface at p faces away from light 0's center (geometric normal n): the light is
// below its horizon, so every shadow technique returns 0 there, as the reference does. Depth
// comparisons mostly find this by themselves; filters and moments blur it with nearby depths,
// and the normal offset can lift a back face out of its own shadow.
bool shadowFacesAway(vec3 p, vec3 n) {
#if SHADOW_PROJECTION == 0
  return dot(n, -uLightDirection) <= 0.0;
#else
  return dot(n, uLightPosition - p) <= 0.0;
#endif
}

// The receiver point after the normal offset (Holbert 2011, "Normal offset shadows"; the papers
// are listed in techniques/common/shadow/README.md).
vec3 shadowReceiver(vec3 p, vec3 geometricNormal) {
  // exercise(shadow_map-normal_offset): begin
  // task: Normal offset. Return the receiver q = p + n * (b * w): the surface point p moved along
  // task: its unit geometric normal n (geometricNormal) by b = uNormalBias map texels
  // task: (shadow.normal_bias), where w = shadowTexelWorld(p) is the world size (scene units) of
  // task: one map texel at p. The offset grows with the texel, so it removes the acne that the
  // task: texel's depth slope causes.
  return p + geometricNormal * (uNormalBias * shadowTexelWorld(p));
  // exercise: stub
  // return p; // no offset: the receiver is the surface point itself
  // exercise: end
}

// Perspective depth in [0,1] of a point at axis distance z (cube faces).
float shadowPerspectiveDepth(float z) {
  float n = uLightNear, f = uLightFar;
  float ndc = (f + n) / (f - n) - 2.0 * f * n / ((f - n) * z);
  return ndc * 0.5 + 0.5;
}

#if SHADOW_PROJECTION == 2
// Cube lookup vector and reference depth; returns false outside [near, far] (treated as lit).
bool shadowCoordCube(vec3 q, out vec3 dir, out float depth) {
  dir = q - uLightPosition;
  vec3 a = abs(dir);
  float z = max(a.x, max(a.y, a.z));
  depth = shadowPerspectiveDepth(z);
  return z > uLightNear && depth <= 1.0;
}
#else
// Map coordinates (uv, depth in [0,1]); returns false outside the light frustum (treated as lit).
bool shadowCoord2D(vec3 q, out vec3 coord) {
  vec4 c = uLightViewProj * vec4(q, 1.0);
  coord = c.xyz / max(abs(c.w), 1e-20) * 0.5 + 0.5;
  if (c.w <= 0.0) return false;
  return all(greaterThanEqual(coord, vec3(0.0))) && all(lessThanEqual(coord, vec3(1.0)));
}
#endif

// Binary visibility of light 0 at receiver q (already offset): 1 lit, 0 shadowed.
float shadowTestHard(vec3 q) {
#if SHADOW_PROJECTION == 2
  vec3 dir;
  float depth;
  if (!shadowCoordCube(q, dir, depth)) return 1.0;
  return texture(uShadowMap, vec4(dir, depth - uConstantBias));
#else
  // exercise(shadow_map-depth_test): begin
  // task: Depth comparison. Project q into the map with shadowCoord2D(q, coord) (coord.xy: map
  // task: uv, coord.z: q's map depth, both in [0,1]); when it returns false, q is outside the
  // task: light's frustum: return 1.0 (lit). Otherwise return 1.0 when the biased receiver depth
  // task: coord.z - uConstantBias (shadow.constant_bias, in the map's [0,1] depth units) is <= the
  // task: depth stored at coord.xy, else 0.0. uShadowMap is a sampler2DShadow (compare mode
  // task: GL_LEQUAL, nearest texel): texture(uShadowMap, vec3(uv, reference)) returns exactly that
  // task: 0/1 comparison of reference with the stored depth.
  vec3 coord;
  if (!shadowCoord2D(q, coord)) return 1.0;
  return texture(uShadowMap, vec3(coord.xy, coord.z - uConstantBias));
  // exercise: stub
  // return 1.0; // lit: no point is in shadow
  // exercise: end
#endif
}

// Linear distance from the light (light-space depth in scene units) of a stored map depth.
float shadowLinearDepth(float d01) {
#if SHADOW_PROJECTION == 0
  return uLightNear + d01 * (uLightFar - uLightNear);
#else
  float ndc = d01 * 2.0 - 1.0;
  return 2.0 * uLightNear * uLightFar / (uLightFar + uLightNear - ndc * (uLightFar - uLightNear));
#endif
}

// Width in scene units that the whole map covers at light-space depth z (constant for
// orthographic maps; grows linearly with z for perspective maps and cube faces).
float shadowMapWidth(float z) {
#if SHADOW_PROJECTION == 0
  return uTexelScale * uMapResolution;
#else
  return z * uTexelScale * uMapResolution;
#endif
}

// Soft-shadow geometry for an area light (PCSS, VSSM, MSM), with uLightSize the disk radius in
// scene units at the light (spot, point) or tan(angular radius) for a directional light.
uniform float uLightSize;

// Radius (texels) of the map region through which a receiver at linear depth zR sees the light,
// taken at the near plane where it is widest (Fernando 2005: grows with zR).
float shadowSearchTexels(float zR) {
#if SHADOW_PROJECTION == 0
  float world = (zR - uLightNear) * uLightSize;
#else
  float world = uLightSize * (zR - uLightNear) / max(zR, 1e-6);
#endif
  return world / shadowMapWidth(uLightNear) * uMapResolution;
}

// Penumbra half-width (texels at the receiver) from similar triangles, blocker at linear depth zB.
float shadowPenumbraTexels(float zR, float zB) {
  // exercise(pcss-penumbra): begin
  // task: Penumbra estimate (Fernando 2005): blocker, receiver and light are parallel planes; by
  // task: similar triangles the penumbra's half-width in world units at the receiver is
  // task: w = (zR - zB) * uLightSize / zB for a spot or point light (uLightSize: the light disk's
  // task: radius) and w = (zR - zB) * uLightSize for a directional light (SHADOW_PROJECTION == 0;
  // task: uLightSize = tan of the cone's angular radius). zR, zB: linear light-space depths of the
  // task: receiver and the mean blocker. Guards: use max(zR - zB, 0.0), and max(zB, 1e-6) as the
  // task: divisor. Return w in map texels at the receiver: w / shadowMapWidth(zR) * uMapResolution.
  float dz = max(zR - zB, 0.0);
#if SHADOW_PROJECTION == 0
  float world = dz * uLightSize;
#else
  float world = dz * uLightSize / max(zB, 1e-6);
#endif
  return world / shadowMapWidth(zR) * uMapResolution;
  // exercise: stub
  // return 0.0; // no penumbra: the filter keeps its minimum radius
  // exercise: end
}
