// Front-to-back compositing with the under operator (Bavoil & Myers 2008, "Order Independent
// Transparency with Dual Depth Peeling", front-to-back peeling; techniques/depth_peeling/README.md).
// The accumulation holds (C, T): C the colour of the layers composited so far (each premultiplied
// by its alpha and by the transmittance of the layers in front of it), T = the product of (1 - a)
// over those layers, the transmittance from the eye to the next layer. It starts at (0, 0, 0, 1).

// The accumulation after the layer `layer` = (a*C, a) (premultiplied; (0, 0, 0, 0) where the
// layer is empty) is composited under it, behind every layer in `acc`.
vec4 compositeUnder(vec4 acc, vec4 layer) {
  // exercise(depth_peeling-under): begin
  // task: The under operator, front to back. acc = (C, T): C the colour composited so far (rgb),
  // task: T the transmittance of those layers (a); layer = (a*C_k, a_k), already premultiplied by
  // task: its alpha a_k. The new layer is seen through T: C' = C + T * (a*C_k), and it lets
  // task: through a fraction (1 - a_k) of what lies behind: T' = T * (1 - a_k). Return (C', T').
  return vec4(acc.rgb + acc.a * layer.rgb, acc.a * (1.0 - layer.a));
  // exercise: stub
  // return vec4(acc.rgb + layer.rgb, acc.a); // added up, nothing in front hides anything
  // exercise: end
}

// The final colour: what lies behind every composited layer (`behind`: the opaque colour, or the
// tail's estimate in front of it) seen through them, i.e. Over of the layers onto it.
vec3 resolveOver(vec4 acc, vec3 behind) {
  // exercise(depth_peeling-resolve): begin
  // task: acc = (C, T) after the last layer (as in compositeUnder). behind is the radiance that
  // task: lies behind all of them (the opaque surface's colour). Return what the eye sees: the
  // task: layers' colour C plus behind, attenuated by the layers' transmittance T.
  return acc.rgb + acc.a * behind;
  // exercise: stub
  // return acc.rgb + behind; // the layers add light but hide nothing
  // exercise: end
}
