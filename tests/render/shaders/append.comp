#version 450
// Appends the squares of the invocation indices below uCount that are multiples of 3 to a storage
// buffer, counting them with an atomic counter (tests/render/test_frame_graph.cpp).
layout(local_size_x = 64) in;
layout(binding = 0) uniform atomic_uint uAppended;
layout(std430, binding = 0) writeonly buffer Items { uint items[]; };
uniform uint uCount;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uCount || i % 3u != 0u) return;
  uint slot = atomicCounterIncrement(uAppended);
  items[slot] = i * i;
}
