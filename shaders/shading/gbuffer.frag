#version 450 core
// G-buffer: world position and linear depth, shading normal and material occlusion, geometric
// normal and coverage, base color and metallic, emissive and roughness. Normals face the camera.
#include "material.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vTangent;
in vec2 vUv;

uniform vec3 uCameraPosition;
uniform vec3 uCameraForward;

layout(location = 0) out vec4 oPosition;  // xyz world position, w linear view depth
layout(location = 1) out vec4 oNormal;    // xyz shading normal, w material occlusion
layout(location = 2) out vec4 oGeometry;  // xyz geometric normal, w coverage (1)
layout(location = 3) out vec4 oAlbedo;    // rgb base color, a metallic
layout(location = 4) out vec4 oMaterial;  // rgb emissive, a roughness

void main() {
  SurfaceMaterial m = sampleMaterial(vUv);
  if (uAlphaMask && m.baseColor.a < uAlphaCutoff) discard;
  vec3 geometric = normalize(cross(dFdx(vWorldPos), dFdy(vWorldPos)));
  vec3 toCamera = uCameraPosition - vWorldPos;
  if (dot(geometric, toCamera) < 0.0) geometric = -geometric;
  vec3 n = shadingNormal(vNormal, vTangent, vUv);
  if (!gl_FrontFacing) n = -n;
  // Keep the shading normal in the visible hemisphere of the geometric one.
  if (dot(n, geometric) < 0.0) n = normalize(n - 1.01 * dot(n, geometric) * geometric);
  oPosition = vec4(vWorldPos, dot(vWorldPos - uCameraPosition, uCameraForward));
  oNormal = vec4(n, m.occlusion);
  oGeometry = vec4(geometric, 1.0);
  oAlbedo = vec4(m.baseColor.rgb, m.metallic);
  oMaterial = vec4(m.emissive, m.roughness);
}
