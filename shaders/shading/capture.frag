#version 450 core
// The transparency reference's fragment capture (framework/shading/fragment_capture.h). The depth
// test against the opaque depth runs before this shader (early_fragment_tests), so a fragment
// behind an opaque surface neither counts nor is captured. CAPTURE_COUNT: count the fragments of
// each row. Otherwise: append the fragments of rows [uFirstRow, uEndRow) (GL rows, bottom up);
// the caller sized the buffer from the counts, and the bound check only guards against a mismatch,
// which the caller detects from the total.
layout(early_fragment_tests) in;

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vTangent;
in vec2 vUv;

#ifdef CAPTURE_COUNT
layout(std430, binding = 0) buffer RowCounts {
  uint uRowCounts[];
};

void main() {
  atomicAdd(uRowCounts[int(gl_FragCoord.y)], 1u);
}
#else
#include "layer.glsl"

struct Fragment {
  uint x, y;
  float depth;
  float r, g, b, alpha;
};
layout(std430, binding = 1) buffer Fragments {
  uint uCount;
  uint uCapacity;
  uint uPad0, uPad1;
  Fragment uFragments[];
};
uniform int uFirstRow;
uniform int uEndRow;
uniform int uHeight;

void main() {
  int row = int(gl_FragCoord.y);
  if (row < uFirstRow || row >= uEndRow) return;
  LayerFragment f = shadeLayer();
  uint i = atomicAdd(uCount, 1u);
  if (i >= uCapacity) return;
  uFragments[i].x = uint(gl_FragCoord.x);
  uFragments[i].y = uint(uHeight - 1 - row);
  uFragments[i].depth = gl_FragCoord.z;
  uFragments[i].r = f.radiance.r;
  uFragments[i].g = f.radiance.g;
  uFragments[i].b = f.radiance.b;
  uFragments[i].alpha = f.alpha;
}
#endif
