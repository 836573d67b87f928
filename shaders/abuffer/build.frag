#version 450 core
// abuffer.build (techniques/abuffer/README.md "Algorithm"; Yang et al. 2010): every transparent
// fragment that passes the depth test against the opaque depth (no depth write, no colour output)
// is shaded (shading/layer.glsl) and appended to its pixel's list: a node index from the atomic
// counter, the pixel's head swapped for it, the node written with the old head as its next.
// Indices at or beyond uCapacity are counted but not stored: the pass reads the counter back and
// rebuilds its band with a larger pool or in smaller parts, so the lists stay consistent.
// Early fragment tests: without them the depth test may run after the shader, and fragments
// hidden by the opaque surface would still append their nodes.
layout(early_fragment_tests) in;

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vTangent;
in vec2 vUv;

#include "../shading/layer.glsl"
#include "node.glsl"

layout(binding = 0, offset = 0) uniform atomic_uint uNodeCount;
layout(r32ui, binding = 0) uniform coherent uimage2D uHeads;
layout(std430, binding = 0) writeonly buffer Nodes { uvec4 nodes[]; };
uniform uint uCapacity;

void main() {
  LayerFragment f = shadeLayer();
  uint index = atomicCounterIncrement(uNodeCount);
  if (index >= uCapacity) return;
  uint next = imageAtomicExchange(uHeads, ivec2(gl_FragCoord.xy), index);
  nodes[index] = abufferPackNode(next, gl_FragCoord.z, f.radiance * f.alpha, f.alpha);
}
