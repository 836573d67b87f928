#version 450
// Reads the appended items and their count as storage buffers and writes (count, sum) (tests/render/test_frame_graph.cpp).
layout(local_size_x = 1) in;
layout(std430, binding = 0) readonly buffer Items { uint items[]; };
layout(std430, binding = 1) readonly buffer Count { uint count; };
layout(std430, binding = 2) writeonly buffer Result { uint result[2]; };

void main() {
  uint sum = 0u;
  for (uint i = 0u; i < count; ++i) sum += items[i];
  result[0] = count;
  result[1] = sum;
}
