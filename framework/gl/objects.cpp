#include "gl/objects.h"

namespace rtlab::gl {

Query::Query(GLenum target, const std::string& label) {
  glCreateQueries(target, 1, &m_name);
  if (!label.empty()) setObjectLabel(GL_QUERY, m_name, label);
}

Query::Query(Query&& o) noexcept : m_name(std::exchange(o.m_name, 0)) {}

Query& Query::operator=(Query&& o) noexcept {
  if (this != &o) {
    reset();
    m_name = std::exchange(o.m_name, 0);
  }
  return *this;
}

void Query::reset() {
  if (m_name) glDeleteQueries(1, &m_name);
  m_name = 0;
}

} // namespace rtlab::gl
