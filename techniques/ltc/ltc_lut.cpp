#include "techniques/ltc/ltc_lut.h"

#include <algorithm>
#include <cmath>

namespace rtlab {
namespace {

// Bilinear interpolation of `channels` floats per cell of an n x n grid at grid coordinates (x, y).
void bilinear(const std::vector<float>& grid, int n, int channels, double x, double y, float* out) {
  const int x0 = std::clamp(int(std::floor(x)), 0, n - 2), y0 = std::clamp(int(std::floor(y)), 0, n - 2);
  const double fx = x - x0, fy = y - y0;
  for (int c = 0; c < channels; ++c) {
    const auto at = [&](int i, int j) { return double(grid[std::size_t((j * n + i) * channels + c)]); };
    const double top = at(x0, y0) * (1 - fx) + at(x0 + 1, y0) * fx;
    const double bottom = at(x0, y0 + 1) * (1 - fx) + at(x0 + 1, y0 + 1) * fx;
    out[c] = float(top * (1 - fy) + bottom * fy);
  }
}

gl::Texture upload(const char* label, GLenum format, GLenum layout, int size, const std::vector<float>& texels) {
  gl::TextureDesc desc;
  desc.format = format;
  desc.width = desc.height = size;
  desc.minFilter = desc.magFilter = GL_LINEAR;
  gl::Texture t(desc, label);
  glTextureSubImage2D(t.id(), 0, 0, 0, size, size, layout, GL_FLOAT, texels.data());
  return t;
}

} // namespace

LtcLutData resampleLtcTable(const LtcTable& table, int size) {
  const int n = table.size;
  LtcLutData out;
  out.size = size;
  out.matrix.resize(std::size_t(4 * size * size));
  out.scale.resize(std::size_t(4 * size * size));
  out.sphere.resize(std::size_t(size * size));
  std::vector<float> lobe(std::size_t(3 * n * n)); // magnitude, fresnel, error interleaved
  for (int k = 0; k < n * n; ++k) {
    lobe[std::size_t(3 * k)] = table.magnitude[std::size_t(k)];
    lobe[std::size_t(3 * k + 1)] = table.fresnel[std::size_t(k)];
    lobe[std::size_t(3 * k + 2)] = table.error[std::size_t(k)];
  }
  for (int j = 0; j < size; ++j) {
    // The grid coordinate of the target's row and column in the fit's grid: exact integers at the
    // fit's own size, so that the copy is exact.
    const double y = double(j) * (n - 1) / (size - 1);
    const int y0 = std::clamp(int(std::floor(y)), 0, n - 2);
    const double fy = y - y0;
    const float diffuseFresnel =
        float(table.diffuseFresnel[std::size_t(y0)] * (1 - fy) + table.diffuseFresnel[std::size_t(y0 + 1)] * fy);
    for (int i = 0; i < size; ++i) {
      const double x = double(i) * (n - 1) / (size - 1);
      const std::size_t k = std::size_t(j * size + i);
      bilinear(table.mInv, n, 4, x, y, &out.matrix[4 * k]);
      float l[3];
      bilinear(lobe, n, 3, x, y, l);
      out.scale[4 * k] = l[0];
      out.scale[4 * k + 1] = l[1];
      out.scale[4 * k + 2] = diffuseFresnel;
      out.scale[4 * k + 3] = l[2];
      bilinear(table.sphere, n, 1, x, y, &out.sphere[k]);
    }
  }
  return out;
}

void LtcLut::build(const LtcLutData& data) {
  m_size = data.size;
  m_matrix = upload("ltc.matrix", GL_RGBA32F, GL_RGBA, data.size, data.matrix);
  m_scale = upload("ltc.scale", GL_RGBA32F, GL_RGBA, data.size, data.scale);
  m_sphere = upload("ltc.sphere", GL_R32F, GL_RED, data.size, data.sphere);
}

std::size_t LtcLut::bytes() const {
  std::size_t total = 0;
  for (const gl::Texture* t : {&m_matrix, &m_scale, &m_sphere})
    if (*t) total += t->desc().bytes();
  return total;
}

} // namespace rtlab
