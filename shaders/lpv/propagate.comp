#version 450 core
// lpv.propagate<k> (techniques/lpv/README.md "Propagation"): one gather step. Every destination
// cell sums, over its six axial neighbours (light travelling along d from the neighbour at -d) and
// the five faces of the destination cell the neighbour sees (the front face and four side faces),
//   Phi_f = dOmega_f * I_src(w_f) * (1 - V_f),
// reprojected as a cosine lobe about the face's normal, (Phi_f / pi) max(0, n_f.w). Not clamped
// here: the step is linear and conserves the band-0 flux (the README's energy section), the
// negative values are clamped where the volume is read. V_f: the geometry volume at the shared
// face, evaluated against the direction the light arrives from (one-sided surfels), in [0, 1].
// The result goes to the next iterate and is added to the sum of iterates.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
#include "sh.glsl"

layout(binding = 0) uniform sampler3D uSrcR;
layout(binding = 1) uniform sampler3D uSrcG;
layout(binding = 2) uniform sampler3D uSrcB;
layout(binding = 3) uniform sampler3D uGeometry; // (N + 1)^3, cell centres at the grid's corners
layout(binding = 0, rgba32f) uniform writeonly image3D uDstR;
layout(binding = 1, rgba32f) uniform writeonly image3D uDstG;
layout(binding = 2, rgba32f) uniform writeonly image3D uDstB;
layout(binding = 3, rgba32f) uniform image3D uSumR;
layout(binding = 4, rgba32f) uniform image3D uSumG;
layout(binding = 5, rgba32f) uniform image3D uSumB;

uniform bool uOcclusion;
uniform bool uFirst;            // the sum starts as the injected volume plus this step
uniform float uFrontSolidAngle; // 0.4006696846 sr and 0.4234413544 sr, scaled so the 30 faces
uniform float uSideSolidAngle;  // sum to exactly 4 pi (lpv::solidAngleNormalisation)

const ivec3 kDirs[6] = ivec3[6](ivec3(1, 0, 0), ivec3(-1, 0, 0), ivec3(0, 1, 0), ivec3(0, -1, 0),
                                ivec3(0, 0, 1), ivec3(0, 0, -1));

void main() {
  ivec3 cell = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(cell, ivec3(uGridSize)))) return;
  vec4 sumR = vec4(0.0), sumG = vec4(0.0), sumB = vec4(0.0);
  for (int i = 0; i < 6; ++i) {
    ivec3 d = kDirs[i];
    ivec3 src = cell - d;
    if (any(lessThan(src, ivec3(0))) || any(greaterThanEqual(src, ivec3(uGridSize)))) continue;
    vec4 r = texelFetch(uSrcR, src, 0), g = texelFetch(uSrcG, src, 0), b = texelFetch(uSrcB, src, 0);
    vec4 blocking = vec4(0.0);
    if (uOcclusion) {
      // The shared face's centre in the geometry volume's texel space: corner k is texel k.
      vec3 face = vec3(cell) + 0.5 - 0.5 * vec3(d);
      blocking = texture(uGeometry, (face + 0.5) / float(uGridSize + 1));
    }
    // exercise(lpv-propagate): begin
    // task: Propagate the neighbour's light (SH intensities r, g, b of the cell at src = cell - d; the
    // task: light travels along d) onto the five faces of this cell that it sees: the front face
    // task: (direction w = d, outward normal n = d, solid angle uFrontSolidAngle) and the four side
    // task: faces (normal n = +-e for the two axes e perpendicular to d, direction from the source's
    // task: centre to the face's centre w = normalize(d + 0.5 n), solid angle uSideSolidAngle). Per face
    // task: and channel the flux is Phi_f = solidAngle * shEval(sh, w) * transmit, where transmit =
    // task: 1 - clamp(shEval(blocking, -w), 0, 1) when uOcclusion (else 1). Reproject it as a point
    // task: light at this cell's centre radiating (Phi_f / pi) max(0, n.w): add
    // task: Phi_f / pi * shCosineLobe(n) to sumR, sumG, sumB. Do not clamp Phi_f (see the README).
    for (int f = 0; f < 5; ++f) {
      vec3 w, n;
      float solidAngle;
      if (f == 0) {
        w = vec3(d);
        n = vec3(d);
        solidAngle = uFrontSolidAngle;
      } else {
        // The two axes perpendicular to d's axis, both signs.
        n = vec3(0.0);
        n[(i / 2 + 1 + ((f - 1) >> 1)) % 3] = (f & 1) == 1 ? 1.0 : -1.0;
        w = normalize(vec3(d) + 0.5 * n);
        solidAngle = uSideSolidAngle;
      }
      float transmit = uOcclusion ? 1.0 - clamp(shEval(blocking, -w), 0.0, 1.0) : 1.0;
      vec4 lobe = shCosineLobe(n) * (solidAngle * transmit / 3.14159265358979);
      sumR += shEval(r, w) * lobe;
      sumG += shEval(g, w) * lobe;
      sumB += shEval(b, w) * lobe;
    }
    // exercise: stub
    // // Stub: a neutral value so that the program compiles and runs. Replace it with your code.
    // // (nothing propagates: the light stays in the injected cells)
    // exercise: end
  }
  imageStore(uDstR, cell, sumR);
  imageStore(uDstG, cell, sumG);
  imageStore(uDstB, cell, sumB);
  if (uFirst) {
    imageStore(uSumR, cell, texelFetch(uSrcR, cell, 0) + sumR);
    imageStore(uSumG, cell, texelFetch(uSrcG, cell, 0) + sumG);
    imageStore(uSumB, cell, texelFetch(uSrcB, cell, 0) + sumB);
  } else {
    imageStore(uSumR, cell, imageLoad(uSumR, cell) + sumR);
    imageStore(uSumG, cell, imageLoad(uSumG, cell) + sumG);
    imageStore(uSumB, cell, imageLoad(uSumB, cell) + sumB);
  }
}
