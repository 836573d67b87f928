#version 450 core
// The floor of a full-screen pass: one texture fetch per pixel and one write (bench/).
in vec2 vUv;
uniform sampler2D uSource;
layout(location = 0) out vec4 oColor;

void main() { oColor = texelFetch(uSource, ivec2(gl_FragCoord.xy), 0); }
