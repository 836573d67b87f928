// Edge-stopping weights of the ao blur and upsampling. aoBilateralWeight (the blur): a tap counts
// fully when it lies on the centre's tangent plane and faces the same way. The plane distance is
// compared with uPlaneSigma (a tenth of ao.radius, since the AO changes on the scale of the
// radius, plus a floor relative to depth for precision); the normal term is (n.n')^8. Sky taps
// (depth 0) get weight 0.
uniform float uPlaneSigma;

float aoBilateralWeight(vec3 p, vec3 n, vec3 q, vec3 m, float qDepth) {
  if (qDepth <= 0.0) return 0.0;
  float sigma = uPlaneSigma + 1e-3 * -p.z;
  float t = dot(n, q - p) / sigma;
  float facing = max(dot(n, m), 0.0);
  facing *= facing;
  facing *= facing;
  return exp(-0.5 * t * t) * facing * facing;
}

// aoPlaneWeight (the upsampling): the weight of a tap (view-space point q, unit normal m, linear
// depth qDepth) for the frame pixel's point p, from p's distance to the tap's tangent plane
// against the same sigma, without a normal term: the frame pixel's own normal is never read (a
// G-buffer fetch per frame pixel; measured cheaper at no higher error, techniques/ssao/README.md
// "Half-resolution upsampling"). Sky taps get weight 0.
float aoPlaneWeight(vec3 q, vec3 m, float qDepth, vec3 p) {
  if (qDepth <= 0.0) return 0.0;
  float t = dot(m, p - q) / (uPlaneSigma + 1e-3 * qDepth);
  return exp(-0.5 * t * t);
}
