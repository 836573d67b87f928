#include "viewer/window/exposure_meter.h"

#include "gl/state.h"

#include <glm/glm.hpp>

#include <vector>

namespace rtlab {

ExposureMeter::~ExposureMeter() { releaseFence(); }

void ExposureMeter::releaseFence() {
  if (m_fence) glDeleteSync(m_fence);
  m_fence = nullptr;
}

bool ExposureMeter::due(std::chrono::steady_clock::time_point now) const {
  return !m_fence && (!m_started || now - m_lastStart >= kInterval);
}

void ExposureMeter::start(const gl::Texture& color, std::chrono::steady_clock::time_point now) {
  releaseFence();
  const glm::ivec2 size(color.desc().width, color.desc().height);
  const glm::ivec2 tiles((size.x + 15) / 16, (size.y + 15) / 16); // kTile in exposure.comp
  m_tileCount = std::size_t(tiles.x) * std::size_t(tiles.y);
  const std::size_t bytes = m_tileCount * sizeof(glm::vec4);
  if (!m_tiles || m_tiles.desc().bytes != bytes) m_tiles = gl::BufferObject({gl::BufferKind::Storage, bytes}, "viewer.exposure_tiles");
  gl::Program& p = m_programs.get({{"viewer/exposure.comp"}, {}, "viewer.exposure"});
  p.use();
  color.bind(0);
  p.set("uColor", 0).set("uSize", size).set("uTiles", tiles);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, m_tiles.id());
  glDispatchCompute(GLuint((m_tileCount + 63) / 64), 1, 1); // local_size_x in exposure.comp
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  gl::restoreKnownState(); // unbinds the program, texture and storage buffer (docs/frame-graph.md)
  m_fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  glFlush(); // so that the fence is reached without a later wait
  m_lastStart = now;
  m_started = true;
}

std::optional<ExposureReadout> ExposureMeter::poll(bool wait) {
  if (!m_fence) return std::nullopt;
  const GLuint64 timeout = wait ? GLuint64(10'000'000'000) : 0; // 10 s, in nanoseconds
  const GLenum state = glClientWaitSync(m_fence, 0, timeout);
  if (state == GL_TIMEOUT_EXPIRED) return std::nullopt;
  releaseFence();
  if (state == GL_WAIT_FAILED) return std::nullopt; // the next start measures again
  ExposureSum sum;
  for (const glm::vec4& t : m_tiles.downloadAs<glm::vec4>()) {
    sum.addPartial(t.x, t.y, std::size_t(t.z));
    sum.addNonFinite(std::size_t(t.w));
  }
  return sum.readout();
}

} // namespace rtlab
