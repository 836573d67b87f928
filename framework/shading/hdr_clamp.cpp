#include "shading/hdr_clamp.h"

#include "util/error.h"

#include <algorithm>

namespace rtlab {

void HdrClampCounters::beginFrame(bool count) {
  m_counting = count;
  if (!count) return;
  if (!m_buffer) {
    m_buffer = gl::Buffer("hdr_clamp.counters");
    glNamedBufferStorage(m_buffer.id(), GLsizeiptr(kMaxPasses * sizeof(GLuint)), nullptr, GL_DYNAMIC_STORAGE_BIT);
  }
  glClearNamedBufferData(m_buffer.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
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
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBinding, m_buffer.id());
  program.set(uniform, index);
}

std::vector<HdrClampCounters::Count> HdrClampCounters::read() const {
  std::vector<Count> out;
  if (!m_buffer) return out;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<GLuint> values(kMaxPasses, 0);
  glGetNamedBufferSubData(m_buffer.id(), 0, GLsizeiptr(values.size() * sizeof(GLuint)), values.data());
  for (std::size_t i = 0; i < m_passes.size(); ++i)
    if (m_used[i]) out.push_back(Count{m_passes[i], values[i]});
  return out;
}

} // namespace rtlab
