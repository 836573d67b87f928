// The LTC tables as the ltc technique samples them (techniques/ltc/README.md "Table size"): the
// fit's table (assets/ltc/ggx.json, techniques/common/arealight/ltc_table.h) resampled to
// ltc.table_size and packed into three linearly filtered float textures.
#pragma once
#include "gl/texture.h"
#include "techniques/common/arealight/ltc_table.h"

#include <cstddef>
#include <vector>

namespace rtlab {

// One table size's texels, rows j (the view axis) outer, columns i (roughness) inner.
struct LtcLutData {
  int size = 0;
  std::vector<float> matrix; // 4 per texel: (a, b, c, d) of M^-1
  std::vector<float> scale;  // 4 per texel: (magnitude, fresnel, diffuse_fresnel of row j, fit error)
  std::vector<float> sphere; // 1 per texel: over (z/2 + 1/2, |F|)
};

// The table at `size` x `size`: texel (i, j) holds the fit's value at the grid point (i/(size-1),
// j/(size-1)) of its axes, interpolated bilinearly between the fit's cells (exactly what a linear
// texture filter of the fit's own table returns there). At the fit's own size it is a copy.
LtcLutData resampleLtcTable(const LtcTable& table, int size);

// The textures the shaders bind as uLtcMatrix, uLtcScale and uLtcSphere (shaders/ltc/lut.glsl).
class LtcLut {
public:
  void build(const LtcLutData& data);
  int size() const { return m_size; }
  std::size_t bytes() const;
  const gl::Texture& matrix() const { return m_matrix; }
  const gl::Texture& scale() const { return m_scale; }
  const gl::Texture& sphere() const { return m_sphere; }

private:
  int m_size = 0;
  gl::Texture m_matrix, m_scale, m_sphere;
};

} // namespace rtlab
