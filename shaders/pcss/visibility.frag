#version 450 core
// Percentage-closer soft shadows (Fernando 2005). 1. Blocker search: the mean linear depth of the
// map texels nearer than the receiver within the region through which the receiver sees the
// light. 2. Penumbra from similar triangles: w = (zR - zB) * lightSize / zB for a disk light of
// radius lightSize at the apex (spot, point), w = (zR - zB) * tan(angle) for a directional light.
// 3. PCF with that radius, clamped to [min, max] penumbra texels. No blocker: fully lit.
// OUTPUT selects what is written: 0 visibility, 1 mean blocker depth (0 near .. 1 far plane,
// 0 without blockers), 2 filter radius / max penumbra.
#include "../shadow/common/shadow_space.glsl"
#include "../shadow/common/shadow_filter.glsl"

in vec2 vUv;
uniform sampler2D uPosition;
uniform sampler2D uGeometry;
#if SHADOW_PROJECTION == 2
uniform samplerCube uShadowRaw;
#else
uniform sampler2D uShadowRaw;
#endif
uniform vec2 uSearchTaps[64];
uniform int uSearchTapCount;
uniform float uMinPenumbra;   // texels
uniform float uMaxPenumbra;   // texels
uniform float uMaxSearch;     // texels

layout(location = 0) out vec4 oValue;

// Receiver: map coordinates, depth in [0,1] and linear depth. False outside the map (lit).
bool receiver(vec3 q, out vec3 coord, out float linearDepth) {
#if SHADOW_PROJECTION == 2
  vec3 dir;
  float depth;
  bool inside = shadowCoordCube(q, dir, depth);
  coord = dir;
  vec3 a = abs(dir);
  linearDepth = max(a.x, max(a.y, a.z));
  coord = dir;
  return inside;
#else
  bool inside = shadowCoord2D(q, coord);
  linearDepth = shadowLinearDepth(coord.z);
  return inside;
#endif
}

// Raw stored depth at a tap offset (texels) around the receiver's map position.
float storedDepth(vec3 coord, vec2 offsetTexels) {
#if SHADOW_PROJECTION == 2
  vec3 onFace, t1, t2;
  cubeFaceFrame(coord, onFace, t1, t2);
  vec2 o = offsetTexels * 2.0 / uMapResolution;
  return texture(uShadowRaw, onFace + o.x * t1 + o.y * t2).r;
#else
  return texture(uShadowRaw, coord.xy + offsetTexels / uMapResolution).r;
#endif
}

float receiverDepth01(vec3 coord, float linearDepth) {
#if SHADOW_PROJECTION == 2
  return shadowPerspectiveDepth(linearDepth);
#else
  return coord.z;
#endif
}

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 geometry = texelFetch(uGeometry, px, 0);
  vec3 p = texelFetch(uPosition, px, 0).xyz;
  vec3 q = shadowReceiver(p, geometry.w > 0.5 ? normalize(geometry.xyz) : vec3(0.0));
  vec3 coord;
  float zR;
  bool inside = receiver(q, coord, zR);

  // 1. Blocker search over the region the light subtends, seen from the receiver, at the near plane.
  float searchTexels = clamp(shadowSearchTexels(zR), 1.0, uMaxSearch);
  float zRef = receiverDepth01(coord, zR) - uConstantBias;
  mat2 rotation = tapRotation();
  float blockerSum = 0.0;
  int blockers = 0;
  // exercise(pcss-blocker): begin
  // task: Blocker search (Fernando 2005), only when the receiver is inside the map (`inside`).
  // task: For each of the uSearchTapCount taps uSearchTaps[i] (points of the unit disk), read the
  // task: raw stored depth d = storedDepth(coord, rotation * uSearchTaps[i] * searchTexels) (offset
  // task: in map texels; rotation, searchTexels and zRef are computed above, and rotation is the
  // task: identity when pcss.rotate is off). A tap with d < zRef (zRef: the receiver's map depth
  // task: minus the constant bias) is a blocker: add its linear depth shadowLinearDepth(d) (scene
  // task: units from the light) to blockerSum and count it in blockers. The code below turns them
  // task: into the mean blocker depth zB = blockerSum / blockers; no blocker means lit.
  if (inside) {
    for (int i = 0; i < uSearchTapCount; ++i) {
      float d = storedDepth(coord, rotation * uSearchTaps[i] * searchTexels);
      if (d < zRef) {
        blockerSum += shadowLinearDepth(d);
        ++blockers;
      }
    }
  }
  // exercise: stub
  // // no blocker found: every receiver is lit
  // exercise: end
  // 2. Penumbra width at the receiver, in map texels.
  float radius = 0.0;
  float zB = 0.0;
  if (blockers > 0) {
    zB = blockerSum / float(blockers);
    radius = shadowPenumbraTexels(zR, zB);
  }
  radius = clamp(radius, uMinPenumbra, uMaxPenumbra);
  // 3. Filter (every lane, for the derivatives of the receiver-plane bias).
  float visibility = shadowFilter(q, radius, uTapCount);
  if (blockers == 0) visibility = 1.0;
  if (geometry.w >= 0.5 && shadowFacesAway(p, normalize(geometry.xyz))) visibility = 0.0;
  float mask = geometry.w < 0.5 ? 0.0 : 1.0;
#if OUTPUT == 1
  float shown = blockers > 0 ? clamp((zB - uLightNear) / (uLightFar - uLightNear), 0.0, 1.0) : 0.0;
  oValue = vec4(vec3(shown * mask), mask);
#elif OUTPUT == 2
  oValue = vec4(vec3(radius / max(uMaxPenumbra, 1e-6) * mask), mask);
#else
  oValue = vec4(visibility * mask);
#endif
}
