// Shared by the ao estimators (ssao, hbao): the view-space surface buffer "ao.view" (xyz
// view-space shading normal, w linear view depth, 0 on sky pixels) at the AO resolution, position
// reconstruction and projection, the blue-noise rotation and the debug-view hook AO_VISIT.
// techniques/common/ao/ao_pass.cpp sets every uniform here.
#include "../../common/constants.glsl"

uniform sampler2D uAoView;   // unit 0
uniform sampler2D uAoNoise;  // unit 1: 64x64 blue noise in [0, 1)
uniform mat4 uProj;          // view -> clip
uniform vec4 uViewRay;       // view xy at depth 1 = fullPx * uViewRay.xy + uViewRay.zw (see ao_pass.cpp)
uniform ivec2 uAoSize;       // size of ao.view (the AO resolution)
uniform ivec2 uFullSize;     // frame size
uniform int uScale;          // 1 full resolution, 2 half: ao.view texel k is frame pixel k * uScale
uniform float uRadius;       // ao.radius, scene units (the view transform is rigid)

struct AoSurface {
  vec3 p;  // view-space position
  vec3 n;  // view-space unit shading normal, facing the camera
  float depth;
};

// View-space position of the surface at linear depth `depth` seen through frame point `fullPx`
// (frame pixels, continuous); perspective camera: the view ray at depth 1, scaled.
vec3 aoViewPosition(vec2 fullPx, float depth) {
  return vec3((fullPx * uViewRay.xy + uViewRay.zw) * depth, -depth);
}

// Frame-pixel center that the AO-resolution texel `px` stands for (ao_pass prepare picks it).
vec2 aoFullPixel(ivec2 px) { return vec2(px * uScale) + 0.5; }

// The unit view-space shading normal from the G-buffer's world-space one (the view transform is
// rigid); a zero normal (degenerate mesh data) is taken to face the camera instead of normalising
// 0/0 into NaN.
vec3 aoViewNormal(mat4 view, vec3 worldNormal) {
  return dot(worldNormal, worldNormal) > 0.0 ? normalize(mat3(view) * worldNormal) : vec3(0.0, 0.0, 1.0);
}

// Linear depth stored at AO texel `px`; 0 on sky pixels.
float aoStoredDepth(ivec2 px) { return texelFetch(uAoView, clamp(px, ivec2(0), uAoSize - 1), 0).w; }

// View-space position of the surface at AO texel `px` with its stored linear depth `depth`
// (meaningless on sky: check depth > 0).
vec3 aoTexelPosition(ivec2 px, float depth) { return aoViewPosition(aoFullPixel(px), depth); }

// AO texels spanned by one scene unit at linear depth `depth` (vertical, perspective camera):
// a world length L projects to about L * aoTexelsPerUnit(depth) texels.
float aoTexelsPerUnit(float depth) {
  return 0.5 * uProj[1][1] * float(uFullSize.y) / (max(depth, 1e-6) * float(uScale));
}

// False on sky pixels (no surface: excluded, the stage writes 0 there and the mask is 0).
bool aoSurface(ivec2 px, out AoSurface s) {
  vec4 v = texelFetch(uAoView, px, 0);
  s.depth = v.w;
  s.n = v.xyz;
  s.p = aoTexelPosition(px, v.w);
  return v.w > 0.0;
}

// Projects a view-space point; false when it is behind the camera (w <= 0) or off-screen,
// where nothing is known and the sample counts as unoccluded. `uv` in [0, 1)^2, `px` its AO texel.
bool aoProject(vec3 q, out vec2 uv, out ivec2 px) {
  vec4 clip = uProj * vec4(q, 1.0);
  uv = vec2(-1.0);
  px = ivec2(0);
  if (clip.w <= 1e-6) return false;
  uv = clip.xy / clip.w * 0.5 + 0.5;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) return false;
  px = min(ivec2(uv * vec2(uFullSize)) / uScale, uAoSize - 1);
  return true;
}

// Blue noise in [0, 1) at AO texel `px`; `channel` 0, 1, ... give differently offset tiles.
float aoNoise(ivec2 px, int channel) {
  return texelFetch(uAoNoise, (px + channel * ivec2(23, 41)) & 63, 0).r;
}

// Orthonormal frame around the unit normal n, turned by `angle` about n (per-pixel rotation).
mat3 aoTangentFrame(vec3 n, float angle) {
  vec3 a = abs(n.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
  vec3 t = normalize(cross(a, n));
  vec3 b = cross(n, t);
  float c = cos(angle), s = sin(angle);
  return mat3(c * t + s * b, -s * t + c * b, n);
}

// Debug view <id>.pattern: the estimator runs once more for the pattern pixel, and AO_VISIT
// (called by the estimator for every sample it takes, with the sample's screen position and its
// occlusion in [0, 1]) marks the samples that land on the current frame pixel.
#ifdef AO_PATTERN
uniform ivec2 uPatternPixel; // AO texel whose samples are shown
bool gPatternActive = false;
vec2 gPatternFrag;           // current frame pixel center
float gPatternMarker;        // marker radius, frame pixels
vec4 gPatternMark = vec4(0.0);
void aoPatternVisit(vec2 uv, float occlusion) {
  if (!gPatternActive) return;
  vec2 d = abs(uv * vec2(uFullSize) - gPatternFrag);
  if (max(d.x, d.y) <= gPatternMarker) gPatternMark = vec4(occlusion, 1.0 - occlusion, 0.0, 1.0);
}
#define AO_VISIT(uv, occlusion) aoPatternVisit(uv, occlusion)
#else
#define AO_VISIT(uv, occlusion)
#endif
