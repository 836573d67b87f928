#version 450 core
// The frame's last step: exposure, tone curve, and (for a window) sRGB encoding. Headless PNG
// output gets its sRGB encoding when the image is written.
#include "../common/color.glsl"

in vec2 vUv;
uniform sampler2D uColor;
uniform float uExposure;
uniform int uOperator;  // tonemap.operator: 0 ACES fit, 1 Reinhard, 2 clamp (no curve)
uniform bool uEncodeSrgb;

layout(location = 0) out vec4 oColor;

void main() {
  vec4 hdr = texelFetch(uColor, ivec2(gl_FragCoord.xy), 0);
  vec3 x = max(hdr.rgb, vec3(0.0)) * uExposure;
  vec3 mapped = uOperator == 0 ? toneAces(x) : uOperator == 1 ? toneReinhard(x) : clamp(x, 0.0, 1.0);
  oColor = vec4(uEncodeSrgb ? linearToSrgb(mapped) : mapped, 1.0);
}
