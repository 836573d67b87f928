// The HDR clamp (docs/stages.md "The HDR clamp"): colour written to a 16-bit float target is
// clamped to the format's largest finite value, 65504, instead of becoming +inf. With
// HDR_CLAMP_COUNT (set only on the frame that stats count, as the atomics cost time on every
// fragment on llvmpipe) each clamped fragment also adds 1 to its pass's counter in the storage
// buffer at binding 7, filled and read by HdrClampCounters (framework/shading/hdr_clamp.cpp;
// kBinding there matches 7 here).
const float kHalfMax = 65504.0;

#ifdef HDR_CLAMP_COUNT
layout(std430, binding = 7) buffer HdrClampCounts {
  uint uHdrClampCounts[];
};
uniform int uHdrClampSlot; // this pass's counter
#endif

// c with every channel at most 65504 (+inf too); counts the fragment once if any channel was above.
vec3 clampHdr(vec3 c) {
#ifdef HDR_CLAMP_COUNT
  if (any(greaterThan(c, vec3(kHalfMax)))) atomicAdd(uHdrClampCounts[uHdrClampSlot], 1u);
#endif
  return min(c, vec3(kHalfMax));
}

// True when a channel of c is NaN or infinite (its exponent bits all set). A bit test rather than
// isnan()/isinf(), which a compiler assuming finite math may fold to false.
bool nonFinite(vec3 c) {
  uvec3 exponent = floatBitsToUint(c) & 0x7f800000u;
  return any(equal(exponent, uvec3(0x7f800000u)));
}

// Counts, in counter `slot`, a value that an earlier pass stored at the 16-bit limit (it was
// clamped there, or was at least 65504 and would have rounded to it).
void countHdrAtLimit(vec3 stored, int slot) {
#ifdef HDR_CLAMP_COUNT
  if (any(greaterThanEqual(stored, vec3(kHalfMax)))) atomicAdd(uHdrClampCounts[slot], 1u);
#endif
}
