#version 450 core
// Scene geometry seen from light 0, passing the linear depth along the light's axis.
layout(location = 0) in vec3 aPosition;
uniform mat4 uModel;
uniform mat4 uViewProj;
uniform vec3 uLightPosition;  // orthographic: the eye of the light's box
uniform vec3 uLightDirection;
out float vDepth;

void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vDepth = dot(world.xyz - uLightPosition, uLightDirection);
  gl_Position = uViewProj * world;
}
