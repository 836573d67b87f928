#version 450 core
// abuffer.resolve (techniques/abuffer/README.md "Algorithm"): per pixel, walk the list the build
// pass appended, keep the MAX_FRAGMENTS nearest fragments sorted front to back in a local array
// (insertion; farther ones are dropped and counted), then composite them with Over onto the
// opaque colour: R = a1 C1 + (1 - a1)(a2 C2 + (1 - a2)(... C_opaque)), summed front to back with
// the transmittance (the same sum; the loop back to front miscompiles on llvmpipe). Equal
// depths are ordered by abufferInFront (node.glsl). Writes the list length to the counts image
// (the debug views) and adds the frame's dropped fragments and largest list length to the stats.
#include "node.glsl"

#ifndef MAX_FRAGMENTS
#define MAX_FRAGMENTS 32
#endif

layout(r32ui, binding = 0) uniform readonly uimage2D uHeads;
layout(r32ui, binding = 1) uniform writeonly uimage2D uCounts;
layout(std430, binding = 0) readonly buffer Nodes { uvec4 nodes[]; };
layout(std430, binding = 1) coherent buffer Stats {
  uint uDroppedFragments;
  uint uMaxComplexity;
};
uniform sampler2D uColor; // the opaque colour (the stage's input)
uniform uint uCapacity;   // nodes in the pool: no valid list is longer or points beyond it

layout(location = 0) out vec4 oColor;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 opaque = texelFetch(uColor, px, 0);

  Fragment kept[MAX_FRAGMENTS]; // kept[0] is the nearest
  int count = 0;
  uint listLength = 0u;
  // Guard: a list is at most uCapacity long, so the walk ends even on a corrupt list.
  for (uint i = imageLoad(uHeads, px).r; i < uCapacity && listLength < uCapacity; i = nodes[i].x) {
    Fragment f = abufferUnpackNode(nodes[i]);
    ++listLength;
    // exercise(abuffer-insert): begin
    // task: Keep the MAX_FRAGMENTS nearest fragments of the pixel in kept[0..count-1], sorted front
    // task: to back: kept[0] nearest. Use abufferInFront(a, b) (true when a goes in front of b) as
    // task: the order. Insertion: when the array is not full (count < MAX_FRAGMENTS), or f is in
    // task: front of the farthest kept fragment kept[MAX_FRAGMENTS - 1], shift every kept fragment
    // task: behind f one place back (when full, the farthest falls off the end: it is dropped) and
    // task: put f in the gap; count grows by one up to MAX_FRAGMENTS. Otherwise f is dropped. (The
    // task: dropped fragments are counted outside this region, as listLength - MAX_FRAGMENTS.)
    if (count < MAX_FRAGMENTS || abufferInFront(f, kept[MAX_FRAGMENTS - 1])) {
      int j = min(count, MAX_FRAGMENTS - 1);
      while (j > 0 && abufferInFront(f, kept[j - 1])) {
        kept[j] = kept[j - 1];
        --j;
      }
      kept[j] = f;
      count = min(count + 1, MAX_FRAGMENTS);
    }
    // exercise: stub
    // // Stub: a neutral value so that the program compiles and runs. Replace it with your code.
    // // (no fragment is kept: the pixel shows the opaque colour)
    // exercise: end
  }

  // exercise(abuffer-over): begin
  // task: Composite the kept fragments with Over onto the opaque colour. Over nests back to front,
  // task: R = p0 + (1 - a0)(p1 + (1 - a1)(... opaque)), with p_k = kept[k].premultiplied = (a*C, a) and
  // task: a_k = p_k.a; expanded, it is the sum front to back of T_k * p_k.rgb, with the transmittance
  // task: T_k = (1 - a_0)...(1 - a_(k-1)) (T_0 = 1), plus T_count * opaque.rgb. Compute it front to
  // task: back, k = 0 .. count - 1 (llvmpipe miscompiles the back-to-front loop over this array:
  // task: techniques/abuffer/README.md "Exercise"). Alpha composites the same way:
  // task: result.a = 1 - T_count * (1 - opaque.a).
  vec3 color = vec3(0.0);
  float transmittance = 1.0;
  for (int k = 0; k < count; ++k) {
    vec4 p = kept[k].premultiplied;
    color += transmittance * p.rgb;
    transmittance *= 1.0 - p.a;
  }
  vec4 result = vec4(color + transmittance * opaque.rgb, 1.0 - transmittance * (1.0 - opaque.a));
  // exercise: stub
  // // Stub: a neutral value so that the program compiles and runs. Replace it with your code.
  // vec4 result = opaque;
  // exercise: end

  uint dropped = listLength > uint(MAX_FRAGMENTS) ? listLength - uint(MAX_FRAGMENTS) : 0u;
  if (dropped > 0u) atomicAdd(uDroppedFragments, dropped);
  if (listLength > uMaxComplexity) atomicMax(uMaxComplexity, listLength);
  imageStore(uCounts, px, uvec4(listLength));
  oColor = result;
}
