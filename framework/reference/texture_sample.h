// Material inputs at a ray hit, as the G-buffer pass reads them (shaders/shading/material.glsl):
// textures sampled bilinearly with repeat wrapping (the GPU's sampler; no mip-mapping: a hit has
// no footprint), sRGB textures decoded to linear.
#pragma once
#include "scene/scene.h"

#include <glm/glm.hpp>

namespace rtlab::reference {

// Linear RGBA at uv (glTF convention: (0,0) is the image's top-left corner).
glm::vec4 sampleTexture(const TextureImage& image, glm::vec2 uv);

// Base color (rgb, alpha) and metallic of a material at uv; `material` may be null (the default
// material: white, dielectric).
struct SurfaceInputs {
  glm::vec4 baseColor{1.0f};
  float metallic = 0.0f;
  glm::vec3 diffuseAlbedo() const { return glm::vec3(baseColor) * (1.0f - metallic); }
};
SurfaceInputs surfaceInputs(const Scene& scene, const Material* material, glm::vec2 uv);

} // namespace rtlab::reference
