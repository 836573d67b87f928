#version 450 core
// The light-space G-buffer of light 0 (techniques/common/rsm/rsm_gbuffer.h), one face per draw:
// for the surface patch seen through each texel, its reflected flux, normal and position.
//   Phi_p = rho * E_perp * A_perp
// rho the diffuse albedo as the lighting pass computes it (base colour times 1 - metallic,
// textures included), E_perp light 0's irradiance on a surface facing it (lightIrradiance(): the
// intensity over d^2, the range window, the spot cone) and A_perp the texel's area perpendicular
// to the ray (rsmPerpendicularArea()). The patch's own area is A_perp / cos, its irradiance
// E_perp cos: the cosines cancel and Phi_p does not depend on the surface's orientation
// (techniques/rsm/README.md "The light-space G-buffer").
#include "../shading/material.glsl"
#include "../common/lights.glsl"
#include "common/rsm.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vTangent;
in vec2 vUv;


layout(location = 0) out vec4 oFlux;
layout(location = 1) out vec4 oNormal;
layout(location = 2) out vec4 oPosition;

void main() {
  SurfaceMaterial m = sampleMaterial(vUv);
  if (uAlphaMask && m.baseColor.a < uAlphaCutoff) discard;
  vec3 toLight;
  vec3 irradiance = lightIrradiance(0, vWorldPos, toLight);
  // The normal on the side the light sees (as the G-buffer turns it toward the camera): the
  // geometric normal decides the side, the shading normal is kept in its hemisphere.
  vec3 geometric = normalize(cross(dFdx(vWorldPos), dFdy(vWorldPos)));
  if (dot(geometric, toLight) < 0.0) geometric = -geometric;
  vec3 n = (gl_FrontFacing ? 1.0 : -1.0) * shadingNormal(vNormal, vTangent, vUv);
  if (dot(n, geometric) < 0.0) n = normalize(n - 1.01 * dot(n, geometric) * geometric);
  vec2 uv = gl_FragCoord.xy / float(uRsmResolution);
  vec3 rho = m.baseColor.rgb * (1.0 - m.metallic);
  oFlux = vec4(rho * irradiance * rsmPerpendicularArea(vWorldPos, uv), 1.0);
  oNormal = vec4(n, 1.0);
  oPosition = vec4(vWorldPos, 1.0);
}
