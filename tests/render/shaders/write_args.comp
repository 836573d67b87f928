#version 450
// Writes indirect dispatch arguments (uGroups, 1, 1) into a storage buffer (tests/render/test_frame_graph.cpp).
layout(local_size_x = 1) in;
layout(std430, binding = 0) writeonly buffer Args { uint args[3]; };
uniform uint uGroups;

void main() {
  args[0] = uGroups;
  args[1] = 1u;
  args[2] = 1u;
}
