#version 450 core
// A transparency technique's error against the exact A-buffer of the same frame
// (techniques/common/transparency/abuffer_error.h): max over R, G, B of the absolute difference.
uniform sampler2D uComposite;
uniform sampler2D uExact;

layout(location = 0) out vec4 oValue;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 d = abs(texelFetch(uComposite, p, 0).rgb - texelFetch(uExact, p, 0).rgb);
  oValue = vec4(vec3(max(max(d.r, d.g), d.b)), 1.0);
}
