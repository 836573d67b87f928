#version 450 core
// abuffer.resolve, a compute shader over the band's pixels (techniques/abuffer/README.md "Algorithm"): per pixel, composite the nearest
// MAX_FRAGMENTS fragments of the list the build pass appended with Over onto the opaque colour,
// R = a1 C1 + (1 - a1)(a2 C2 + (1 - a2)(... C_opaque)), front to back with the transmittance;
// farther fragments are dropped and counted. The fragments are taken in depth order by selection:
// each step walks the list for the nearest fragment behind the one composited last (equal depths
// ordered by abufferInFront, node.glsl; identical fragments taken together, as many as there are).
// A compute shader rather than a full-screen triangle: llvmpipe 22.3 clips that triangle into two
// and loses lanes of these loops in the 2x2 quads the two halves share along the frame's diagonal
// (README "Numerical guards"); a compute grid has no quads. Writes the list length to
// the counts image (the debug views) and adds the frame's dropped fragments and largest list
// length to the stats.
#include "node.glsl"

#ifndef MAX_FRAGMENTS
#define MAX_FRAGMENTS 32
#endif

layout(local_size_x = 8, local_size_y = 8) in;

layout(r32ui, binding = 0) uniform readonly uimage2D uHeads;
layout(rgba16f, binding = 2) uniform writeonly image2D uOutput; // the composited colour
layout(r32ui, binding = 1) uniform writeonly uimage2D uCounts;
layout(std430, binding = 0) readonly buffer Nodes { uvec4 nodes[]; };
layout(std430, binding = 1) coherent buffer Stats {
  uint uDroppedFragments;
  uint uMaxComplexity;
};
uniform sampler2D uColor; // the opaque colour (the stage's input)
uniform uint uCapacity;   // nodes in the pool: no valid list is longer or points beyond it
uniform ivec2 uOrigin;    // the band's (or part's) first pixel and size
uniform ivec2 uSize;

void main() {
  if (any(greaterThanEqual(gl_GlobalInvocationID.xy, uvec2(uSize)))) return;
  ivec2 px = uOrigin + ivec2(gl_GlobalInvocationID.xy);
  vec4 opaque = texelFetch(uColor, px, 0);
  uint head = imageLoad(uHeads, px).r;
  // Guard: a list is at most uCapacity long, so every walk ends even on a corrupt list.
  uint listLength = 0u;
  for (uint i = head; i < uCapacity && listLength < uCapacity; i = nodes[i].x) ++listLength;

  vec3 color = vec3(0.0);
  float transmittance = 1.0;
  int composited = 0;     // fragments composited so far, at most MAX_FRAGMENTS
  uvec4 last = uvec4(0u); // the fragment composited last (its .yzw)
  bool any = false;       // whether `last` is set
  bool done = false;
  // A lane whose fragments are all composited idles through the remaining steps with `done` set.
  for (int step = 0; step < MAX_FRAGMENTS; ++step) {
    if (!done) {
      // exercise(abuffer-select): begin
      // task: Find the nearest fragment behind `last`: walk the list (node index i from `head`,
      // task: next = nodes[i].x, listLength nodes) and, among the nodes f = nodes[i] with
      // task: abufferInFront(last, f) (every node while `any` is false), keep in `nearest` the one
      // task: in front of all others (abufferInFront(f, nearest)) and in `copies` how many nodes
      // task: are identical to it (same .yzw: the same depth and colour); copies = 0 when there is
      // task: none.
      uvec4 nearest = uvec4(0u);
      uint copies = 0u;
      uint i = head;
      for (uint n = 0u; n < listLength; ++n) {
        uvec4 f = nodes[i];
        i = f.x;
        if (!any || abufferInFront(last, f)) {
          if (copies == 0u || abufferInFront(f, nearest)) {
            nearest = f;
            copies = 1u;
          } else if (all(equal(f.yzw, nearest.yzw))) {
            ++copies;
          }
        }
      }
      // exercise: stub
      // // Stub: a neutral value so that the program compiles and runs. Replace it with your code.
      // uvec4 nearest = uvec4(0u);
      // uint copies = 0u;
      // exercise: end
      done = copies == 0u;
      last = nearest;
      any = true;
      vec4 p = abufferPremultiplied(nearest);
      for (uint c = 0u; c < copies && composited < MAX_FRAGMENTS; ++c) {
        // exercise(abuffer-over): begin
        // task: Composite one fragment p = (a*C, a) (premultiplied colour and coverage) behind the
        // task: ones composited so far. Over nests back to front, R = p0 + (1 - a0)(p1 + (1 - a1)(...
        // task: opaque)); expanded, it is the sum front to back of T_k * p_k.rgb with the
        // task: transmittance T_k = (1 - a_0)...(1 - a_(k-1)) (T_0 = 1), plus T * opaque.rgb at the
        // task: end: add this fragment's term to `color` and update `transmittance`.
        color += transmittance * p.rgb;
        transmittance *= 1.0 - p.a;
        // exercise: stub
        // // Stub: a neutral value so that the program compiles and runs. Replace it with your code.
        // // (the fragment adds nothing: the pixel shows the opaque colour)
        // exercise: end
        ++composited;
      }
      done = done || composited >= MAX_FRAGMENTS;
    }
  }
  // Alpha composites the same way: A = a + (1 - a) A.
  vec4 result = vec4(color + transmittance * opaque.rgb, 1.0 - transmittance * (1.0 - opaque.a));

  uint dropped = listLength > uint(MAX_FRAGMENTS) ? listLength - uint(MAX_FRAGMENTS) : 0u;
  if (dropped > 0u) atomicAdd(uDroppedFragments, dropped);
  if (listLength > uMaxComplexity) atomicMax(uMaxComplexity, listLength);
  imageStore(uCounts, px, uvec4(listLength));
  imageStore(uOutput, px, result);
}
