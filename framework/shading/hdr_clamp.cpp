#include "shading/hdr_clamp.h"

#include "frame/frame_graph.h"
#include "util/error.h"

#include <algorithm>

namespace rtlab {

void HdrClampCounters::beginFrame(bool count) {
  m_counting = count;
  if (!count) return;
  if (!m_buffer) m_buffer = gl::BufferObject({gl::BufferKind::Storage, kMaxPasses * sizeof(GLuint)}, kResource);
  m_buffer.clear();
  m_used.assign(m_passes.size(), false);
}

int HdrClampCounters::slot(const std::string& pass) const {
  const auto it = std::find(m_passes.begin(), m_passes.end(), pass);
  if (it != m_passes.end()) return int(it - m_passes.begin());
  if (int(m_passes.size()) >= kMaxPasses)
    throw Error(ExitCode::Internal, "more than " + std::to_string(kMaxPasses) + " passes use the HDR clamp counters");
  m_passes.push_back(pass);
  m_used.push_back(false);
  return int(m_passes.size()) - 1;
}

void HdrClampCounters::bind(gl::Program& program, const std::string& pass, const char* uniform) const {
  if (!m_counting) return;
  const int index = slot(pass);
  m_used[std::size_t(index)] = true;
  program.set(uniform, index);
}

void HdrClampCounters::declareUse(const FrameGraph& frame, PassBuilder& b) {
  if (frame.isImported(kResource)) b.readWriteBuffer(kResource, BufferBinding::Storage, kBinding);
}

std::vector<HdrClampCounters::Count> HdrClampCounters::read() const {
  std::vector<Count> out;
  if (!m_buffer) return out;
  // Not a target of the frame (that would keep the passes that count, e.g. lighting for a
  // visibility-only frame), so the read-back after the frame issues its own barrier.
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const std::vector<GLuint> values = m_buffer.downloadAs<GLuint>();
  for (std::size_t i = 0; i < m_passes.size(); ++i)
    if (m_used[i]) out.push_back(Count{m_passes[i], values[i]});
  return out;
}

} // namespace rtlab
