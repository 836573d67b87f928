#version 450 core
// G-buffer: world position and linear depth, shading normal and material occlusion, geometric
// normal and coverage, base color and metallic, emissive and roughness, and the shadow terminator
// rule's shading point and smooth normal (docs/measuring.md). Normals face the camera. Emission is
// clamped to 65504 (docs/stages.md "The HDR clamp"); the lighting pass counts the clamped pixels.
#include "material.glsl"
#include "../common/hdr.glsl"
#include "../common/terminator.glsl"

in vec3 gWorldPos;
in vec3 gNormal;
in vec4 gTangent;
in vec2 gUv;
in vec3 gBarycentric;
flat in vec3 gTriPosition[3];
flat in vec3 gTriNormal[3];

uniform vec3 uCameraPosition;
uniform vec3 uCameraForward;

layout(location = 0) out vec4 oPosition;       // xyz world position, w linear view depth
layout(location = 1) out vec4 oNormal;         // xyz shading normal, w material occlusion
layout(location = 2) out vec4 oGeometry;       // xyz geometric normal, w coverage (1)
layout(location = 3) out vec4 oAlbedo;         // rgb base color, a metallic
layout(location = 4) out vec4 oMaterial;       // rgb emissive, a roughness
layout(location = 5) out vec4 oShadowPosition; // xyz shading point (terminator rule), w coverage (1)
layout(location = 6) out vec4 oShadowNormal;   // xyz smooth (vertex) normal, w coverage (1)

// Keeps a normal in the visible hemisphere of the geometric one.
vec3 intoHemisphere(vec3 n, vec3 geometric) {
  return dot(n, geometric) < 0.0 ? normalize(n - 1.01 * dot(n, geometric) * geometric) : n;
}

void main() {
  SurfaceMaterial m = sampleMaterial(gUv);
  if (uAlphaMask && m.baseColor.a < uAlphaCutoff) discard;
  vec3 geometric = normalize(cross(dFdx(gWorldPos), dFdy(gWorldPos)));
  vec3 toCamera = uCameraPosition - gWorldPos;
  if (dot(geometric, toCamera) < 0.0) geometric = -geometric;
  float side = gl_FrontFacing ? 1.0 : -1.0;
  vec3 n = intoHemisphere(side * shadingNormal(gNormal, gTangent, gUv), geometric);
  vec3 smoothNormal = intoHemisphere(side * normalize(gNormal), geometric);
  // The vertex normals on the side the triangle is seen from: a back face curves the other way.
  vec3 n0 = side * normalize(gTriNormal[0]), n1 = side * normalize(gTriNormal[1]), n2 = side * normalize(gTriNormal[2]);
  vec3 b = gBarycentric / max(gBarycentric.x + gBarycentric.y + gBarycentric.z, 1e-20);
  vec3 shadingPoint = terminatorPoint(gWorldPos, b, gTriPosition[0], gTriPosition[1], gTriPosition[2], n0, n1, n2);
  oPosition = vec4(gWorldPos, dot(gWorldPos - uCameraPosition, uCameraForward));
  oNormal = vec4(n, m.occlusion);
  oGeometry = vec4(geometric, 1.0);
  oAlbedo = vec4(m.baseColor.rgb, m.metallic);
  oMaterial = vec4(min(m.emissive, vec3(kHalfMax)), m.roughness);
  oShadowPosition = vec4(shadingPoint, 1.0);
  oShadowNormal = vec4(smoothNormal, 1.0);
}
