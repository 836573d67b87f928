#version 450 core
// Debug view: the light-space depth map of light 0 as linear depth, 0 at the light's near plane
// and 1 at its far plane (perspective depth is linearized, or it would all look white). A 2D map
// fills the frame; a cube map is shown unwrapped by longitude (x) and latitude (y) around it.
in vec2 vUv;
#if SHADOW_PROJECTION == 2
uniform samplerCube uDepth;
#else
uniform sampler2D uDepth;
#endif
uniform float uNear;
uniform float uFar;

float linearDepth(float d) {
#if SHADOW_PROJECTION == 0
  return d;
#else
  float ndc = d * 2.0 - 1.0;
  float z = 2.0 * uNear * uFar / (uFar + uNear - ndc * (uFar - uNear));
  return (z - uNear) / (uFar - uNear);
#endif
}

layout(location = 0) out vec4 oValue;

void main() {
#if SHADOW_PROJECTION == 2
  float lon = (vUv.x * 2.0 - 1.0) * 3.14159265;
  float lat = (vUv.y - 0.5) * 3.14159265;
  vec3 dir = vec3(cos(lat) * sin(lon), sin(lat), -cos(lat) * cos(lon));
  float d = texture(uDepth, dir).r;
#else
  float d = texture(uDepth, vUv).r;
#endif
  oValue = vec4(vec3(linearDepth(d)), 1.0);
}
