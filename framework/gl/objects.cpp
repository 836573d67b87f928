#include "gl/objects.h"

namespace rtlab::gl {

Query::Query(GLenum target, const std::string& label) {
  // GL_ARB_pipeline_statistics_query's targets (GL_VERTICES_SUBMITTED_ARB 0x82EE ..
  // GL_CLIPPING_OUTPUT_PRIMITIVES_ARB 0x82F7): Mesa's glCreateQueries refuses them
  // (GL_INVALID_ENUM). A generated name becomes a query of its target at its first glBeginQuery;
  // until then there is no object to label.
  if (target >= 0x82EE && target <= 0x82F7) {
    glGenQueries(1, &m_name);
    return;
  }
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
