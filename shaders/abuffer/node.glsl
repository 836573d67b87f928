// One A-buffer node (techniques/abuffer/README.md "Memory"): 16 bytes in the storage buffer of
// nodes (binding 0), a uvec4 of
//   x: the index of the next node of the same pixel's list (kEndOfList ends it),
//   y: the fragment's window depth gl_FragCoord.z as float bits,
//   z: packHalf2x16(a*C.r, a*C.g), w: packHalf2x16(a*C.b, a): the premultiplied colour and the
//      coverage in 16-bit floats (a*C <= 65504 since C is clamped there and a <= 1).
// The head of each pixel's list is in an r32ui image (kEndOfList: empty).
const uint kEndOfList = 0xffffffffu;

uvec4 abufferPackNode(uint next, float depth, vec3 premultipliedColor, float alpha) {
  return uvec4(next, floatBitsToUint(depth), packHalf2x16(premultipliedColor.rg),
               packHalf2x16(vec2(premultipliedColor.b, alpha)));
}

// The node's premultiplied colour and coverage (a*C, a).
vec4 abufferPremultiplied(uvec4 node) { return vec4(unpackHalf2x16(node.z), unpackHalf2x16(node.w)); }

// True when node a is composited in front of node b: the nearer depth first; equal depths
// (coplanar layers) by their packed colour bits, smaller first, so that the result depends on the
// fragments only, never on the order the GPU appended them in (two fragments equal in depth and
// colour are interchangeable). Window depths lie in [0, 1], where the order of the float bits as
// unsigned integers is the order of the depths.
bool abufferInFront(uvec4 a, uvec4 b) {
  return a.y < b.y || (a.y == b.y && (a.z < b.z || (a.z == b.z && a.w < b.w)));
}
