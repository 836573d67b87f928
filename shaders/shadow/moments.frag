#version 450 core
// Moments of light-space depth for filterable shadow maps: depth is linear and normalized,
// z = (distance along the light's axis - near) / (far - near), so filtering averages real depths.
// MOMENTS 2: (z, z^2) (variance shadow maps, Donnelly & Lauritzen 2006).
// MOMENTS 4: (z, z^2, z^3, z^4) (moment shadow maps, Peters & Klein 2015); with OPTIMIZED the
// affine transform of the paper's section 4.3 ("optimized moment quantization") that makes
// 16-bit storage usable.
in float vDepth;
uniform float uLightNear;
uniform float uLightFar;
layout(location = 0) out vec4 oMoments;

#ifdef OPTIMIZED
// Peters & Klein 2015, section 4.3: b' = M^T (z, z^2, z^3, z^4) + (0.035955884801, 0, 0, 0).
const mat4 kOptimize = mat4(-2.07224649, 13.7948857237, 0.105877704, 9.7924062118,
                            32.23703778, -59.4683975703, -1.9077466311, -33.7652110555,
                            -68.571074599, 82.0359750338, 9.3496555107, 47.9456096605,
                            39.3703274134, -35.364903257, -6.6543490743, -23.9728048165);
#endif

void main() {
  float z = clamp((vDepth - uLightNear) / (uLightFar - uLightNear), 0.0, 1.0);
  float z2 = z * z;
#if MOMENTS == 2
  oMoments = vec4(z, z2, 0.0, 0.0);
#elif defined(OPTIMIZED)
  oMoments = kOptimize * vec4(z, z2, z2 * z, z2 * z2) + vec4(0.035955884801, 0.0, 0.0, 0.0);
#else
  oMoments = vec4(z, z2, z2 * z, z2 * z2);
#endif
}
