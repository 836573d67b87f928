#version 450 core
// lpv.lookup (techniques/lpv/README.md "Lookup"): the stage output `indirect`, the irradiance at
// each surface pixel from the sum of the propagated volumes. The cell's intensity I(w) over the
// cell's cross-section s^2 is the radiance of the light travelling along w, so
//   E(x, n) = (1/s^2) * integral I(w) max(0, -n.w) dw = max(0, <I, cosine lobe about -n>) / s^2,
// the SH dot product of the trilinearly filtered volume with the clamped cosine around -n (light
// arriving at the surface travels against n). Negative results (SH ringing) are clamped to 0.
// The volume is read lpv.lookup_offset cells in front of the surface: read at the surface, a wall
// on a cell face would average the cells on both of its sides, and light on the far side (the
// outside of a closed room) would leak in.
#include "sh.glsl"



in vec2 vUv;
layout(location = 0) out vec4 oIndirect;

uniform sampler2D uPosition;
uniform sampler2D uNormal;
uniform sampler2D uGeometry;
uniform sampler3D uSumR;
uniform sampler3D uSumG;
uniform sampler3D uSumB;
uniform float uIntensity;
uniform float uLookupOffset; // in cells, along n: the volume is read in front of the surface

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  if (texelFetch(uGeometry, px, 0).w <= 0.0) {
    oIndirect = vec4(0.0);
    return;
  }
  vec3 p = texelFetch(uPosition, px, 0).xyz;
  vec3 n = normalize(texelFetch(uNormal, px, 0).xyz);
  vec3 uvw = (lpvCellCoord(p) + uLookupOffset * n) / float(uGridSize);
  vec4 lobe = shCosineLobe(-n);
  vec3 e = vec3(dot(texture(uSumR, uvw), lobe), dot(texture(uSumG, uvw), lobe), dot(texture(uSumB, uvw), lobe));
  oIndirect = vec4(max(e, vec3(0.0)) * (uIntensity / (uCellSize * uCellSize)), 1.0);
}
