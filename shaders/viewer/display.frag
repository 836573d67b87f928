#version 450 core
// The viewer's picture (framework/viewer/window/frame_display.cpp): image A alone, or A and B
// split by a vertical wipe at uDivider, or the heat map of |A - B|. Each side is either a
// tone-mapped color image (sRGB-encoded here) or data mapped from [uMin, uMax] to [0, 1], in gray
// or, for one-channel data, through a false-color ramp. Mode 3 draws the scale bar itself, so
// the bar and the picture share one ramp.
#include "../common/color.glsl"

in vec2 vUv;
uniform sampler2D uA;
uniform sampler2D uB;
uniform int uKindA;      // 0: tone-mapped color, 1: data
uniform int uKindB;
uniform int uChannelsA;  // 1 or 3
uniform int uChannelsB;
uniform float uMin;
uniform float uMax;
uniform bool uFalseColor;
uniform int uMode;       // 0: A only, 1: wipe A | B, 2: difference heat map, 3: the colour scale
uniform float uDivider;  // wipe position, fraction of the width from the left
uniform float uDividerPx; // half width of the divider line in uv units

layout(location = 0) out vec4 oColor;

// A ramp through dark blue, magenta, orange and pale yellow: monotonic in lightness, so a
// brighter color always means a larger value.
vec3 falseColor(float t) {
  const vec3 keys[5] = vec3[5](vec3(0.02, 0.01, 0.10), vec3(0.30, 0.07, 0.50), vec3(0.75, 0.21, 0.45),
                               vec3(0.98, 0.56, 0.25), vec3(0.99, 0.98, 0.75));
  float x = clamp(t, 0.0, 1.0) * 4.0;
  int i = min(int(x), 3);
  return mix(keys[i], keys[i + 1], x - float(i));
}

float scalarOf(vec3 v, int channels) { return channels == 1 ? v.r : dot(v, vec3(0.2126, 0.7152, 0.0722)); }

// What one side shows, already display-encoded.
vec3 side(sampler2D image, int kind, int channels) {
  vec3 v = texture(image, vUv).rgb;
  if (kind == 0) return linearToSrgb(clamp(v, 0.0, 1.0));
  vec3 t = (v - vec3(uMin)) / max(uMax - uMin, 1e-20);
  if (channels == 1) return uFalseColor ? falseColor(t.r) : vec3(clamp(t.r, 0.0, 1.0));
  return clamp(t, 0.0, 1.0);
}

void main() {
  if (uMode == 3) { // the bar labelling a data view: its values from min (left) to max (right)
    oColor = vec4(uFalseColor ? falseColor(vUv.x) : vec3(vUv.x), 1.0);
    return;
  }
  if (uMode == 2) {
    vec3 a = texture(uA, vUv).rgb, b = texture(uB, vUv).rgb;
    float d = abs(scalarOf(a, uChannelsA) - scalarOf(b, uChannelsB));
    oColor = vec4(falseColor(d / max(uMax - uMin, 1e-20)), 1.0);
    return;
  }
  vec3 c = (uMode == 1 && vUv.x > uDivider) ? side(uB, uKindB, uChannelsB) : side(uA, uKindA, uChannelsA);
  if (uMode == 1 && abs(vUv.x - uDivider) < uDividerPx) c = vec3(1.0, 0.85, 0.2);
  oColor = vec4(c, 1.0);
}
