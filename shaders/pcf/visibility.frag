#version 450 core
// Percentage-closer filtering (Reeves, Salesin & Cook 1987): the fraction of light 0's depth
// comparisons that pass over a kernel of uTapCount taps within uRadius texels of the receiver.
#include "../shadow/common/shadow_space.glsl"
#include "../shadow/common/shadow_filter.glsl"

in vec2 vUv;
uniform sampler2D uPosition;
uniform sampler2D uGeometry;
uniform float uRadius; // texels

layout(location = 0) out float oVisibility;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 geometry = texelFetch(uGeometry, px, 0);
  vec3 p = texelFetch(uPosition, px, 0).xyz;
  vec3 q = shadowReceiver(p, geometry.w > 0.5 ? normalize(geometry.xyz) : vec3(0.0));
  float visibility = shadowFilter(q, uRadius, uTapCount); // every lane: derivatives inside
  if (geometry.w >= 0.5 && shadowFacesAway(p, normalize(geometry.xyz))) visibility = 0.0;
  oVisibility = geometry.w < 0.5 ? 0.0 : visibility;
}
