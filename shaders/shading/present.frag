#version 450 core
// Shows a tone-mapped frame in the window: sRGB-encodes it for the default framebuffer.
#include "../common/color.glsl"

in vec2 vUv;
uniform sampler2D uImage;

layout(location = 0) out vec4 oColor;

void main() { oColor = vec4(linearToSrgb(texture(uImage, vUv).rgb), 1.0); }
