#version 450 core
// Transparent surfaces without a transparency technique: each layer (shading/layer.glsl) drawn
// back to front per object with premultiplied over-blending (ONE, ONE_MINUS_SRC_ALPHA). The colour
// is clamped to 65504 before the alpha weighting, so the blend onto a clamped opaque colour stays
// finite too.
in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vTangent;
in vec2 vUv;

#include "layer.glsl"

layout(location = 0) out vec4 oColor;

void main() {
  LayerFragment f = shadeLayer();
  oColor = vec4(f.radiance * f.alpha, f.alpha);
}
