#version 450
// Counts its invocations with an atomic counter (tests/render/test_frame_graph.cpp).
layout(local_size_x = 64) in;
layout(binding = 0) uniform atomic_uint uInvocations;

void main() { atomicCounterIncrement(uInvocations); }
