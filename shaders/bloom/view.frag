#version 450 core
// bloom's debug views (RGBA32F, A = mask). VIEW_BRIGHT: the bright pass. VIEW_LEVELS: the mip
// levels 1..uLevelCount (at most 8) side by side at their own resolution, level 1 in the top-left
// quarter and each next level right of the one before, along the top edge; mask 0 elsewhere and
// with the gaussian method (uLevelCount 0).
layout(location = 0) out vec4 oValue;

#ifdef VIEW_BRIGHT
uniform sampler2D uBright;
void main() { oValue = vec4(texelFetch(uBright, ivec2(gl_FragCoord.xy), 0).rgb, 1.0); }
#else
uniform sampler2D uLevels[8];
uniform int uLevelCount;
uniform ivec2 uFrameSize;

vec3 fetchLevel(int j, ivec2 p) {
  switch (j) {
  case 1: return texelFetch(uLevels[0], p, 0).rgb;
  case 2: return texelFetch(uLevels[1], p, 0).rgb;
  case 3: return texelFetch(uLevels[2], p, 0).rgb;
  case 4: return texelFetch(uLevels[3], p, 0).rgb;
  case 5: return texelFetch(uLevels[4], p, 0).rgb;
  case 6: return texelFetch(uLevels[5], p, 0).rgb;
  case 7: return texelFetch(uLevels[6], p, 0).rgb;
  default: return texelFetch(uLevels[7], p, 0).rgb;
  }
}

void main() {
  // Image rows run top to bottom; GL's y runs bottom to top.
  ivec2 px = ivec2(int(gl_FragCoord.x), uFrameSize.y - 1 - int(gl_FragCoord.y));
  int x0 = 0;
  oValue = vec4(0.0);
  for (int j = 1; j <= uLevelCount; ++j) {
    ivec2 size = max(uFrameSize >> j, ivec2(1));
    if (px.x >= x0 && px.x < x0 + size.x && px.y < size.y) {
      ivec2 p = ivec2(px.x - x0, size.y - 1 - px.y);
      oValue = vec4(fetchLevel(j, p), 1.0);
      return;
    }
    x0 += size.x;
  }
}
#endif
