#version 450 core
// The lpv debug views (techniques/lpv/README.md "Debug views"), one per define:
//   VIEW_SLICE     lpv.slice: the horizontal slice lpv.slice_layer of the summed volume over the
//                  whole frame (x right, z down), its fluence flux / s^2 per channel (the integral
//                  of the radiance over all directions);
//   VIEW_INJECTED  lpv.injected: at each surface pixel, the fluence of the injected volume's cell
//                  containing it (0 outside the injected cells);
//   VIEW_GEOMETRY  lpv.geometry: at each surface pixel, the largest blocking probability of the
//                  geometry volume's cell nearest to it, max over w of V(w), clamped to [0, 1].
#include "sh.glsl"

in vec2 vUv;
layout(location = 0) out vec4 oValue;

uniform sampler2D uPosition;
uniform sampler2D uGeometry;
uniform sampler3D uVolumeR;
uniform sampler3D uVolumeG;
uniform sampler3D uVolumeB;
uniform int uSliceLayer;

vec3 fluence(ivec3 cell) {
  return vec3(shFlux(texelFetch(uVolumeR, cell, 0)), shFlux(texelFetch(uVolumeG, cell, 0)),
              shFlux(texelFetch(uVolumeB, cell, 0))) / (uCellSize * uCellSize);
}

void main() {
#ifdef VIEW_SLICE
  ivec2 c = min(ivec2(vUv * float(uGridSize)), ivec2(uGridSize - 1));
  oValue = vec4(fluence(ivec3(c.x, uSliceLayer, uGridSize - 1 - c.y)), 1.0);
#else
  ivec2 px = ivec2(gl_FragCoord.xy);
  if (texelFetch(uGeometry, px, 0).w <= 0.0) {
    oValue = vec4(0.0);
    return;
  }
  vec3 cell = lpvCellCoord(texelFetch(uPosition, px, 0).xyz);
#ifdef VIEW_INJECTED
  ivec3 k = ivec3(floor(cell));
  bool inside = all(greaterThanEqual(k, ivec3(0))) && all(lessThan(k, ivec3(uGridSize)));
  oValue = vec4(inside ? fluence(k) : vec3(0.0), 1.0);
#else
  ivec3 k = clamp(ivec3(floor(cell + 0.5)), ivec3(0), ivec3(uGridSize));
  vec4 v = texelFetch(uVolumeR, k, 0);
  float peak = v.x * kShY00 + length(v.yzw) * kShY1;
  oValue = vec4(vec3(clamp(peak, 0.0, 1.0)), 1.0);
#endif
#endif
}
