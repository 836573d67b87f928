#version 450 core
// HBAO (Bavoil, Sainz & Dimitrov 2008), raw: uDirections directions around each pixel, rotated
// per pixel, each marched for uSteps taps out to ao.radius projected into pixels; the horizon
// each direction finds bounds the open part of its slice of the hemisphere (march.glsl).
// Background pixels get 0. At half resolution a target pixel reads the G-buffer pixel at twice
// its coordinates.
#include "march.glsl"

layout(location = 0) out float oAo;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy) * uGbufferStep;
  Center c;
  oAo = loadCenter(px, c) ? ambientOcclusion(c, pixelJitter(px)) : 0.0;
}
