#version 450
// One colour everywhere (tests/render/test_frame_graph.cpp).
uniform vec4 uColor;
out vec4 fragColor;

void main() { fragColor = uColor; }
