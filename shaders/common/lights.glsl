// Scene lights in a uniform buffer (binding 0), filled by GpuCommon::uploadLights
// (framework/shading/gpu_common.cpp). A uniform buffer, not a storage buffer: on llvmpipe the
// lighting pass took 29 ms instead of 43 ms at 1280x720 (bench/run.sh). kMaxLights must match
// GpuCommon::kMaxLights.
// Units follow glTF: directional lux, point/spot candela, rectangular nits.
const int kLightDirectional = 0;
const int kLightPoint = 1;
const int kLightSpot = 2;
const int kLightRect = 3;

struct GpuLight {
  vec4 positionType;    // xyz position, w type
  vec4 directionRange;  // xyz direction light travels, w range (0 = infinite)
  vec4 colorIntensity;  // rgb color, w intensity
  vec4 spotCos;         // x cos(inner), y cos(outer), z rect: 1 two-sided, 0 front face only
  vec4 rectRight;       // xyz right axis, w width
  vec4 rectUp;          // xyz up axis, w height
};

const int kMaxLights = 64;
layout(std140, binding = 0) uniform LightBlock {
  GpuLight uLights[kMaxLights];
};
uniform int uLightCount;

// Irradiance arriving at p from light i (on a surface facing it), and the direction toward it.
// Rectangular lights are approximated as a point at their center with intensity
// radiance * area * cos(emission angle) (|cos| for a two-sided one). While an arealight technique runs, the lighting pass skips
// rectangular lights (SKIP_RECT_LIGHTS) and the technique adds them (docs/stages.md); the
// transparent fallback pass keeps this approximation for transparent surfaces.
vec3 lightIrradiance(int i, vec3 p, out vec3 toLight) {
  GpuLight light = uLights[i];
  int type = int(light.positionType.w);
  vec3 radiant = light.colorIntensity.rgb * light.colorIntensity.w;
  if (type == kLightDirectional) {
    toLight = -light.directionRange.xyz;
    return radiant;
  }
  vec3 d = light.positionType.xyz - p;
  float dist2 = max(dot(d, d), 1e-8);
  toLight = d * inversesqrt(dist2);
  float attenuation = 1.0 / dist2;
  float range = light.directionRange.w;
  if (range > 0.0) {
    float r = sqrt(dist2) / range;
    attenuation *= clamp(1.0 - r * r * r * r, 0.0, 1.0) * clamp(1.0 - r * r * r * r, 0.0, 1.0);
  }
  float cosEmit = dot(-toLight, light.directionRange.xyz);
  if (type == kLightSpot) {
    attenuation *= smoothstep(light.spotCos.y, light.spotCos.x, cosEmit);
  } else if (type == kLightRect) {
    float facing = light.spotCos.z > 0.5 ? abs(cosEmit) : max(cosEmit, 0.0);
    attenuation *= facing * light.rectRight.w * light.rectUp.w;
  }
  return radiant * attenuation;
}
