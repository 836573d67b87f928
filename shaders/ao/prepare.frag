#version 450 core
// ao.view: the view-space shading normal and linear view depth of the frame pixel that each AO
// texel stands for (frame pixel k * uScale: the top-left of its 2x2 block at half resolution),
// depth 0 on sky pixels. One fetch per estimator tap instead of three G-buffer reads.
#include "common/ao_common.glsl"

in vec2 vUv;
uniform sampler2D uPosition;
uniform sampler2D uNormal;
uniform sampler2D uGeometry;
uniform mat4 uView;

layout(location = 0) out vec4 oView;

void main() {
  ivec2 px = min(ivec2(gl_FragCoord.xy) * uScale, uFullSize - 1);
  if (texelFetch(uGeometry, px, 0).w < 0.5) {
    oView = vec4(0.0);
    return;
  }
  oView = vec4(aoViewNormal(uView, texelFetch(uNormal, px, 0).xyz), max(texelFetch(uPosition, px, 0).w, 1e-6));
}
