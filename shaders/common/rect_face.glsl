// The emitting faces of the rectangular lights as the camera sees them (docs/contract.md "Area
// lights": drawn into `color` only, never into the G-buffer, the shadow maps or the reference's
// geometry). Without an arealight technique the lighting pass draws them; with one
// (SKIP_RECT_LIGHTS), the technique's composite does (techniques/common/arealight), so the face is
// never lit as if it were the surface behind it. Needs lights.glsl.

// The unit direction of the camera ray through the centre of window pixel `fragCoord` (xy of
// gl_FragCoord), from the inverse view-projection and the camera position.
vec3 cameraRayDirection(vec2 fragCoord, vec2 viewportSize, mat4 invViewProj, vec3 cameraPosition) {
  vec2 ndc = fragCoord / viewportSize * 2.0 - 1.0;
  vec4 far = invViewProj * vec4(ndc, 1.0, 1.0);
  return normalize(far.xyz / far.w - cameraPosition);
}

// True when the ray origin + t dir (dir unit) meets an emitting face of a rectangular light at
// 0 < t < tMax; `radiance` is then the nearest face's L_e (colour times intensity, nits). A
// one-sided light emits along its direction, so the viewer sees its face when dot(dir, direction)
// < 0; a two-sided light shows both faces. The back of a one-sided light is not drawn.
bool rectLightFace(vec3 origin, vec3 dir, float tMax, out vec3 radiance) {
  radiance = vec3(0.0);
  bool hit = false;
  float nearest = tMax;
  for (int i = 0; i < uLightCount; ++i) {
    GpuLight light = uLights[i];
    if (int(light.positionType.w) != kLightRect) continue;
    vec3 normal = light.directionRange.xyz;
    float facing = dot(dir, normal);
    if (abs(facing) < 1e-8 || (facing > 0.0 && light.spotCos.z < 0.5)) continue;
    float t = dot(light.positionType.xyz - origin, normal) / facing;
    if (t <= 0.0 || t >= nearest) continue;
    vec3 q = origin + t * dir - light.positionType.xyz;
    if (abs(dot(q, light.rectRight.xyz)) > 0.5 * light.rectRight.w || abs(dot(q, light.rectUp.xyz)) > 0.5 * light.rectUp.w)
      continue;
    nearest = t;
    radiance = light.colorIntensity.rgb * light.colorIntensity.w;
    hit = true;
  }
  return hit;
}

// The face in front of the G-buffer's surface at pixel `fragCoord` (or of the background when
// `surface` is false), for a full-screen pass.
bool rectLightFaceAtPixel(vec2 fragCoord, vec2 viewportSize, mat4 invViewProj, vec3 cameraPosition, bool surface,
                          vec3 surfacePosition, out vec3 radiance) {
  vec3 dir = cameraRayDirection(fragCoord, viewportSize, invViewProj, cameraPosition);
  float tMax = surface ? distance(surfacePosition, cameraPosition) : 3.0e38;
  return rectLightFace(cameraPosition, dir, tMax, radiance);
}
