#version 450
// Writes f(voxel) = vec4(voxel, 1) / 16 into every voxel of a 3D image (tests/render/test_frame_graph.cpp).
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(rgba16f, binding = 0) writeonly uniform image3D uVolume;
uniform ivec3 uSize;

void main() {
  ivec3 voxel = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(voxel, uSize))) return;
  imageStore(uVolume, voxel, vec4(vec3(voxel), 16.0) / 16.0);
}
