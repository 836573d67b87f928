#version 450 core
// The moment map's texels as a shader reads them (tests/render/test_moment_model.cpp): the same
// texelFetch of a sampler2D as sat.comp's row pass, written out as floats. glGetTextureImage converts
// a normalized 16-bit format on the CPU, exactly; a GPU's texture unit may round that conversion
// differently (an NVIDIA H100 did, by an ulp, in some texels), and the 64-bit table keeps every
// bit of it.
layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2D uMoments;
layout(std430, binding = 0) writeonly buffer Texels { vec4 texels[]; };
uniform int uSize;

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= uSize * uSize) return;
  texels[i] = texelFetch(uMoments, ivec2(i % uSize, i / uSize), 0);
}
