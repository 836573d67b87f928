#version 450 core
// The arealight technique's last pass (techniques/common/arealight/arealight_composite.h): the
// colour it is handed plus the radiance the rectangular lights add, or a light's emitting face
// where the camera sees one in front of the surface. Clamped to 65504 (docs/stages.md).
#include "../common/hdr.glsl"
#include "../common/lights.glsl"
#include "../common/rect_face.glsl"

uniform sampler2D uColor;
uniform sampler2D uArealight;
uniform sampler2D uPosition;
uniform sampler2D uGeometry;
uniform vec3 uCameraPosition;
uniform mat4 uInvViewProj;
uniform vec2 uViewportSize;

layout(location = 0) out vec4 oColor;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 color = texelFetch(uColor, px, 0);
  bool surface = texelFetch(uGeometry, px, 0).w >= 0.5;
  vec3 face;
  if (rectLightFaceAtPixel(gl_FragCoord.xy, uViewportSize, uInvViewProj, uCameraPosition, surface,
                           texelFetch(uPosition, px, 0).xyz, face)) {
    oColor = vec4(clampHdr(face), color.a);
    return;
  }
  vec3 added = surface ? texelFetch(uArealight, px, 0).rgb : vec3(0.0);
  oColor = vec4(clampHdr(color.rgb + added), color.a);
}
