#version 450 core
// Depth is written by the rasterizer; nothing to shade.
void main() {}
