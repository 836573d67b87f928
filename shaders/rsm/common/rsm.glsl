// The light-space G-buffer of light 0 (techniques/common/rsm/rsm_gbuffer.h), shared by rsm and
// lpv: the maps, the light-space projection, and the VPL each texel stands for. bindRsm() sets
// every uniform here (the G-buffer pass itself sets all but the samplers).
//
// Faces: one layer for an orthographic (directional) or perspective (spot) map, six for a cube
// (+X -X +Y -Y +Z -Z, each a 90-degree perspective view). Map coordinates: uv in [0, 1]^2 on a
// face, texel (i, j) covers [i, i + 1) / resolution.
const int kRsmOrthographic = 0;
const int kRsmPerspective = 1;
const int kRsmCube = 2;

uniform sampler2DArray uRsmFlux;     // rgb Phi_p, a = 1 on surface
uniform sampler2DArray uRsmNormal;   // xyz n_p (facing light 0), a = 1 on surface
uniform sampler2DArray uRsmPosition; // xyz x_p, a = 1 on surface
uniform int uRsmProjection;          // kRsmOrthographic, kRsmPerspective, kRsmCube
uniform int uRsmResolution;          // texels per side
uniform mat4 uRsmViewProj[6];        // world -> clip per face ([0] only unless cube)
uniform mat4 uRsmInvViewProj[6];     // clip -> world
uniform vec3 uRsmLightPosition;      // perspective and cube: the light's position
uniform vec3 uRsmLightDirection;     // unit direction the light points (orthographic: travels)
// World size of one texel: orthographic, constant; perspective and cube, per unit of distance
// along the face's axis (LightSpace::texelScale: 2 tan(fov / 2) / resolution).
uniform float uRsmTexelScale;

struct RsmVpl {
  vec3 flux;     // Phi_p
  vec3 normal;   // n_p, unit, facing the light
  vec3 position; // x_p
};

// The cube face whose axis is nearest the direction d (the order of the faces above).
int rsmCubeFace(vec3 d) {
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0 ? 2 : 3;
  return d.z >= 0.0 ? 4 : 5;
}

// Map uv of world point p on face `face` (may lie outside [0, 1]); false behind the face's eye.
bool rsmProjectOnFace(vec3 p, int face, out vec2 uv) {
  vec4 c = uRsmViewProj[face] * vec4(p, 1.0);
  uv = vec2(-1.0);
  if (c.w <= 1e-12) return false;
  uv = c.xy / c.w * 0.5 + 0.5;
  return true;
}

// The face and map uv where world point p projects (for a cube, the face its direction from the
// light falls on). False when it is behind a perspective light.
bool rsmLocate(vec3 p, out int face, out vec2 uv) {
  face = uRsmProjection == kRsmCube ? rsmCubeFace(p - uRsmLightPosition) : 0;
  return rsmProjectOnFace(p, face, uv);
}

// A map point given as uv on `face`, possibly past the face's edge, resolved to the face and uv
// that store it: 2D maps have nothing outside [0, 1]^2 (false); on a cube the point goes through
// the cube lookup by its direction from the light (the neighbouring face).
bool rsmResolve(int face, vec2 uv, out int outFace, out vec2 outUv) {
  outFace = face;
  outUv = uv;
  bool inside = all(greaterThanEqual(uv, vec2(0.0))) && all(lessThan(uv, vec2(1.0)));
  if (inside) return true;
  if (uRsmProjection != kRsmCube) return false;
  vec4 far = uRsmInvViewProj[face] * vec4(uv * 2.0 - 1.0, 1.0, 1.0);
  vec3 d = far.xyz / far.w - uRsmLightPosition;
  outFace = rsmCubeFace(d);
  rsmProjectOnFace(uRsmLightPosition + d, outFace, outUv);
  outUv = clamp(outUv, vec2(0.0), vec2(1.0 - 0.5 / float(uRsmResolution)));
  return true;
}

// The VPL of texel (i, j) of `face`; false where light 0 sees nothing.
bool rsmFetch(ivec2 texel, int face, out RsmVpl v) {
  ivec3 t = ivec3(clamp(texel, ivec2(0), ivec2(uRsmResolution - 1)), face);
  vec4 flux = texelFetch(uRsmFlux, t, 0);
  v.flux = flux.rgb;
  v.normal = texelFetch(uRsmNormal, t, 0).xyz;
  v.position = texelFetch(uRsmPosition, t, 0).xyz;
  return flux.a > 0.5;
}

// The VPL stored at map uv of `face` (the texel containing it).
bool rsmFetchUv(vec2 uv, int face, out RsmVpl v) {
  return rsmFetch(ivec2(floor(uv * float(uRsmResolution))), face, v);
}

// Distance of world point p along the light's axis for `face` (perspective and cube).
float rsmAxisDistance(vec3 p, int face) {
  vec3 d = p - uRsmLightPosition;
  if (uRsmProjection == kRsmCube) return abs(d[face / 2]);
  return dot(d, uRsmLightDirection);
}

// World size of one texel at x_p (its side, perpendicular to the face's axis).
float rsmTexelFootprint(vec3 xp, int face) {
  if (uRsmProjection == kRsmOrthographic) return uRsmTexelScale;
  return uRsmTexelScale * max(rsmAxisDistance(xp, face), 0.0);
}

// A_perp: the area of the texel's patch at x_p measured perpendicular to the light's ray through
// it. Orthographic: texelScale^2. Perspective and cube: |x_p - light|^2 times the texel's solid
// angle, texelScale^2 cos^3(theta) at the angle theta between the ray (through map uv) and the
// face's axis: tan(theta)^2 = |ndc * tan(fov / 2)|^2, tan(fov / 2) = texelScale * resolution / 2.
float rsmPerpendicularArea(vec3 xp, vec2 uv) {
  float s2 = uRsmTexelScale * uRsmTexelScale;
  if (uRsmProjection == kRsmOrthographic) return s2;
  vec2 t = (uv * 2.0 - 1.0) * (0.5 * uRsmTexelScale * float(uRsmResolution));
  float cos2 = 1.0 / (1.0 + dot(t, t));
  vec3 d = xp - uRsmLightPosition;
  return dot(d, d) * s2 * cos2 * sqrt(cos2);
}
