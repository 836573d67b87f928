#version 450 core
// SSAO (Mittring 2007, in the normal-oriented hemisphere form): uSampleCount points within
// ao.radius of the surface point, each occluded when the surface stored at its projection is
// nearer the camera than the point (beyond uBias) and, with the range check, near enough to the
// point. Defines: KERNEL_SPHERE (the classic sphere-volume kernel, 2(1 - occluded fraction)),
// else a cosine-distributed hemisphere about the normal, whose unoccluded fraction estimates
// (1/pi) * integral of V cos; LENGTH_CENTER (lengths mix(0.1, 1, s^2), concentrated near the
// point), else lengths uniform in the volume along each direction (cube root).
#include "../ao/common/ao_common.glsl"

uniform int uSampleCount;
uniform float uBias;     // scene units
uniform float uPower;    // contrast exponent on the result
uniform int uRangeCheck; // 0 off, 1 smooth (Crytek: smoothstep(0, 1, R/|dz|)), 2 occluder within R
uniform bool uRotate;    // per-pixel rotation and length offset from blue noise

// Van der Corput radical inverse in base 2.
float radicalInverse(uint i) { return float(bitfieldReverse(i)) * 2.3283064365386963e-10; }

// Kernel point i of n in the tangent frame (z along the normal), length <= 1. Directions follow
// a golden-angle spiral (stratified in the area of the projected disk or in z), lengths a
// radical-inverse sequence shifted by `jitter`.
vec3 kernelPoint(int i, int n, float jitter) {
  float u = (float(i) + 0.5) / float(n);
  float phi = float(i) * 2.399963229728653;
#ifdef KERNEL_SPHERE
  float z = 1.0 - 2.0 * u; // uniform on the sphere
  float r = sqrt(max(1.0 - z * z, 0.0));
#else
  float r = sqrt(u); // Malley: uniform on the disk lifted to the hemisphere is cosine-distributed
  float z = sqrt(max(1.0 - u, 0.0));
#endif
  float v = fract(radicalInverse(uint(i)) + jitter);
#if defined(LENGTH_CENTER)
  float len = mix(0.1, 1.0, v * v);
#elif defined(LENGTH_SHELL)
  float len = 1.0;
#else
  float len = pow(max(v, 1e-3), 1.0 / 3.0);
#endif
  return len * vec3(r * cos(phi), r * sin(phi), z);
}

float aoEvaluate(ivec2 px, AoSurface s) {
  float angle = uRotate ? 2.0 * kPi * aoNoise(px, 0) : 0.0;
  float jitter = uRotate ? aoNoise(px, 1) : 0.0;
  mat3 frame = aoTangentFrame(s.n, angle);
  // exercise(ssao-kernel-test): begin
  // task: The kernel test. Inputs: the surface point s.p (view space: the camera sits at the origin
  // task: and looks down -z), its linear depth s.depth, the tangent frame `frame` (columns: two
  // task: tangents and the normal, turned by the per-pixel angle) and `jitter`; uRadius = ao.radius
  // task: and uBias = ssao.bias are in scene units.
  // task: For each i < uSampleCount:
  // task: 1. the sample q = s.p + uRadius * (frame * kernelPoint(i, uSampleCount, jitter));
  // task: 2. project it: aoProject(q, uv, tap) (out vec2 uv, out ivec2 tap) returns false behind
  // task:    the camera or off screen, where the sample is unoccluded (occlusion 0);
  // task: 3. read the stored linear depth d = aoStoredDepth(tap) (0 on sky, which never occludes);
  // task:    the sample's own depth is -q.z. It is occluded (occlusion 1) when d > 0 and
  // task:    d < -q.z - uBias;
  // task: 4. range check of an occluded sample, by uRangeCheck: 0 none (keep 1); 1 smooth (Crytek):
  // task:    occlusion = smoothstep(0, 1, uRadius / max(|s.depth - d|, 1e-4)); 2 distance:
  // task:    occlusion = 1 when the stored point aoTexelPosition(tap, d) lies within uRadius
  // task:    of s.p, else 0;
  // task: 5. call AO_VISIT(uv, occlusion) (the ssao.pattern debug view; no effect on the image) and
  // task:    add the occlusion to a sum.
  // task: Output: float visible = 1 - (sum of the occlusions) / uSampleCount, the unoccluded
  // task: fraction (the code below doubles it for the sphere kernel, and applies uPower).
  float occluded = 0.0;
  for (int i = 0; i < uSampleCount; ++i) {
    vec3 q = s.p + uRadius * (frame * kernelPoint(i, uSampleCount, jitter));
    vec2 uv;
    ivec2 tap;
    float occlusion = 0.0;
    if (aoProject(q, uv, tap)) {
      float stored = aoStoredDepth(tap); // 0 on sky: never occludes
      if (stored > 0.0 && stored < -q.z - uBias) {
        occlusion = 1.0;
        if (uRangeCheck == 1) {
          occlusion = smoothstep(0.0, 1.0, uRadius / max(abs(s.depth - stored), 1e-4));
        } else if (uRangeCheck == 2) {
          vec3 occluder = aoTexelPosition(tap, stored);
          occlusion = distance(occluder, s.p) <= uRadius ? 1.0 : 0.0;
        }
      }
    }
    AO_VISIT(uv, occlusion);
    occluded += occlusion;
  }
  float visible = 1.0 - occluded / float(max(uSampleCount, 1));
  // exercise: stub
  // // no kernel point is tested, so none is occluded: AO 1 (unoccluded) everywhere
  // float visible = 1.0;
  // exercise: end
#ifdef KERNEL_SPHERE
  visible = clamp(2.0 * visible, 0.0, 1.0); // half the sphere lies behind a flat surface
#endif
  return pow(visible, uPower);
}

#include "../ao/common/ao_main.glsl"
