#version 450 core
// One draw of the transparent geometry for depth peeling (techniques/depth_peeling/README.md):
// the same program for every layer and the tail, so that each fragment's window depth is computed
// by the same code in every pass and compares equal to the depth an earlier layer stored for it.
// uMode:
//  0 first layer: every fragment; the fixed-function test (GL_LESS against a depth target that
//    starts as the opaque depth) keeps the front-most one in front of the opaque surface;
//  1 later layer: also discards fragments at or in front of the previous layer's depth (the peel);
//  2 tail: the fragments behind the last layer and in front of the opaque surface (tested here,
//    no depth target), their (a*C, a) for the additive sum and a for the product of (1 - a);
//  3 remaining: the same fragments as 2, each written as 1 for an additive count.
// Layers write the premultiplied (a*C, a) of shading/layer.glsl's fragment.
// COUNT_REMAINING (the counting frame's tail): each tail fragment adds 1 to uRemaining[0].
in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vTangent;
in vec2 vUv;

#include "../shading/layer.glsl"

layout(binding = 5) uniform sampler2D uPreviousDepth; // modes 1-3: the depth of the layer before
layout(binding = 6) uniform sampler2D uOpaqueDepth;   // modes 2-3: the opaque depth
uniform int uMode;

#ifdef COUNT_REMAINING
layout(std430, binding = 0) buffer RemainingCount {
  uint uRemaining[];
};
#endif

layout(location = 0) out vec4 oColor;  // layers and tail: (a*C, a); remaining: (1, 0, 0, 0)
layout(location = 1) out vec4 oReveal; // tail: a (blended as dst * (1 - a))

// True when the fragment at window depth z lies at or in front of the depth `previous` that the
// layer before peeled at this pixel: it was composited already (or is coplanar with what was).
bool peeledBefore(float z, float previous) {
  // exercise(depth_peeling-peel): begin
  // task: The peel test. z = gl_FragCoord.z is this fragment's window depth (0 near, 1 far) and
  // task: previous the depth the layer before stored at this pixel (its front-most fragment
  // task: behind the layers before it; the opaque depth where it found none). Return true when
  // task: the fragment belongs to an earlier layer, i.e. lies at or in front of previous: it is
  // task: then discarded, and the depth test picks the nearest of the fragments behind previous.
  // task: Fragments exactly at previous (the stored one, and any coplanar one) count as peeled.
  return z <= previous;
  // exercise: stub
  // return false; // nothing is peeled: every layer finds the front-most fragment again
  // exercise: end
}

void main() {
  float z = gl_FragCoord.z;
  ivec2 px = ivec2(gl_FragCoord.xy);
  if (uMode != 0 && peeledBefore(z, texelFetch(uPreviousDepth, px, 0).r)) discard;
  if (uMode >= 2) {
    // The tail has no depth target: the opaque surface's test (GL_LESS) is made here.
    if (z >= texelFetch(uOpaqueDepth, px, 0).r) discard;
#ifdef COUNT_REMAINING
    atomicAdd(uRemaining[0], 1u);
#endif
    if (uMode == 3) {
      oColor = vec4(1.0, 0.0, 0.0, 0.0);
      oReveal = vec4(0.0);
      return;
    }
  }
  LayerFragment f = shadeLayer();
  oColor = vec4(f.radiance * f.alpha, f.alpha);
  oReveal = vec4(f.alpha);
}
