#version 450 core
// wboit.count (only when the view wboit.complexity is requested): 1 per transparent fragment in
// front of the opaque depth, summed by additive blending into an R32F target (exact to 2^24).
layout(location = 0) out vec4 oCount;

void main() { oCount = vec4(1.0); }
