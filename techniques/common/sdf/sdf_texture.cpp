#include "techniques/common/sdf/sdf_texture.h"

namespace rtlab {

void SdfTexture::update(const Scene& scene, int resolution, int padding) {
  const bool sameSize = m_built && resolution == m_resolution && padding == m_padding;
  if (sameSize && !m_checkHash) return;
  const std::uint64_t hash = sdf::geometryHash(scene);
  m_checkHash = false;
  if (sameSize && hash == m_hash) {
    ++m_cacheHits;
    return;
  }
  const sdf::Volume volume = sdf::buildVolume(scene, resolution, padding);
  gl::TextureDesc d;
  d.target = GL_TEXTURE_3D;
  // 16-bit floats: 11 significant bits keep distances near surfaces (where the march decides)
  // to well below the hit threshold; techniques/sdf_shadow/README.md "The SDF" has the measurement.
  d.format = GL_R16F;
  d.width = volume.grid.dims.x;
  d.height = volume.grid.dims.y;
  d.depth = volume.grid.dims.z;
  d.minFilter = d.magFilter = GL_LINEAR;
  d.wrap = GL_CLAMP_TO_EDGE;
  if (!m_texture || m_texture.desc() != d) m_texture = gl::Texture(d, m_label);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage3D(m_texture.id(), 0, 0, 0, 0, d.width, d.height, d.depth, GL_RED, GL_FLOAT, volume.distance.data());
  m_grid = volume.grid;
  m_hash = hash;
  m_resolution = resolution;
  m_padding = padding;
  m_buildMs = volume.buildMs;
  m_built = true;
  ++m_builds;
}

void SdfTexture::bind(gl::Program& program, int unit) const {
  m_texture.bind(GLuint(unit));
  program.set("uSdf", unit)
      .set("uSdfOrigin", m_grid.origin)
      .set("uSdfSize", m_grid.size())
      .set("uSdfPadding", m_grid.padding);
}

} // namespace rtlab
