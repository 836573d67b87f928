// The bright pass of bloom (docs/contract.md "Bloom"; techniques/bloom/README.md): the share of a
// colour that blooms, from its Rec. 709 luma, with a quadratic soft knee around the threshold so
// that the output changes continuously as the luma crosses it. HARD_CUT gives the hard threshold
// luma > T ? c : 0 instead (bloom.hard_cut), which pops.
const vec3 kLumaWeights = vec3(0.2126, 0.7152, 0.0722);

uniform float uThreshold; // T = bloom.threshold (luma)
uniform float uKnee;      // K = bloom.knee x T, so 0 <= K <= T

// The factor w of bright(c) = c * w, in [0, 1].
float bloomBrightWeight(vec3 c) {
  float luma = dot(c, kLumaWeights);
#ifdef HARD_CUT
  return luma > uThreshold ? 1.0 : 0.0;
#else
  // exercise(bloom-bright): begin
  // task: The soft-knee bright pass. With luma as above, T = uThreshold and K = uKnee:
  // task: q = clamp(luma - T + K, 0, 2K) (0 below T - K, 2K above T + K);
  // task: w = max(q^2 / (4K + 1e-5), luma - T) / max(luma, 1e-5) (the 1e-5 keep K = 0 and black
  // task: pixels finite); return max(w, 0.0). Below T - K nothing blooms, far above T the
  // task: bright part is c * (luma - T) / luma, and in between the quadratic joins the two smoothly.
  float q = clamp(luma - uThreshold + uKnee, 0.0, 2.0 * uKnee);
  float w = max(q * q / (4.0 * uKnee + 1e-5), luma - uThreshold) / max(luma, 1e-5);
  return max(w, 0.0);
  // exercise: stub
  // return luma > uThreshold ? 1.0 : 0.0; // the hard cut: pops at the threshold
  // exercise: end
#endif
}
