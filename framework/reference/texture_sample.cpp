#include "reference/texture_sample.h"

#include <array>
#include <cmath>

namespace rtlab::reference {
namespace {

// sRGB to linear for the 256 byte values (IEC 61966-2-1).
const std::array<float, 256>& srgbTable() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) {
      const float c = float(i) / 255.0f;
      t[std::size_t(i)] = c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
    }
    return t;
  }();
  return table;
}

int wrap(int i, int n) {
  const int r = i % n;
  return r < 0 ? r + n : r;
}

glm::vec4 texel(const TextureImage& image, int x, int y) {
  const std::uint8_t* p = &image.rgba8[(std::size_t(y) * image.width + x) * 4];
  if (image.srgb) {
    const auto& t = srgbTable();
    return {t[p[0]], t[p[1]], t[p[2]], float(p[3]) / 255.0f}; // alpha is always linear
  }
  return glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f;
}

} // namespace

glm::vec4 sampleTexture(const TextureImage& image, glm::vec2 uv) {
  if (image.width <= 0 || image.height <= 0 || image.rgba8.size() < std::size_t(image.width) * image.height * 4)
    return glm::vec4(1.0f); // the GPU binds nothing usable either: treat as white
  // Texel centres at (i + 0.5) / size, as GL samples.
  const float fx = uv.x * float(image.width) - 0.5f, fy = uv.y * float(image.height) - 0.5f;
  if (!std::isfinite(fx) || !std::isfinite(fy)) return texel(image, 0, 0);
  const float x0f = std::floor(fx), y0f = std::floor(fy);
  const float ax = fx - x0f, ay = fy - y0f;
  const int x0 = wrap(int(std::fmod(x0f, float(image.width))), image.width);
  const int y0 = wrap(int(std::fmod(y0f, float(image.height))), image.height);
  const int x1 = wrap(x0 + 1, image.width), y1 = wrap(y0 + 1, image.height);
  const glm::vec4 top = glm::mix(texel(image, x0, y0), texel(image, x1, y0), ax);
  const glm::vec4 bottom = glm::mix(texel(image, x0, y1), texel(image, x1, y1), ax);
  return glm::mix(top, bottom, ay);
}

SurfaceInputs surfaceInputs(const Scene& scene, const Material* material, glm::vec2 uv) {
  SurfaceInputs s;
  if (!material) return s;
  s.baseColor = material->baseColor;
  s.metallic = material->metallic;
  const auto texture = [&](int index) -> const TextureImage* {
    return index >= 0 && index < int(scene.textures.size()) ? &scene.textures[std::size_t(index)] : nullptr;
  };
  if (const TextureImage* t = texture(material->baseColorTexture)) s.baseColor *= sampleTexture(*t, uv);
  if (const TextureImage* t = texture(material->metallicRoughnessTexture)) s.metallic *= sampleTexture(*t, uv).z;
  s.metallic = glm::clamp(s.metallic, 0.0f, 1.0f);
  return s;
}

} // namespace rtlab::reference
