// RAII, move-only ownership of one GL object name. Each GL object kind is a Handle with its own
// create/delete functions (objects.h); a default-constructed Handle owns nothing.
#pragma once
#include "gl/debug.h"
#include "gl/gl.h"

#include <string>
#include <utility>

namespace rtlab::gl {

template <typename Traits>
class Handle {
public:
  Handle() = default;
  explicit Handle(const std::string& label) : m_name(Traits::create()) {
    if (!label.empty()) setObjectLabel(Traits::kIdentifier, m_name, label);
  }
  ~Handle() { reset(); }
  Handle(Handle&& o) noexcept : m_name(std::exchange(o.m_name, 0)) {}
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      m_name = std::exchange(o.m_name, 0);
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  GLuint id() const { return m_name; }
  explicit operator bool() const { return m_name != 0; }
  void reset() {
    if (m_name) Traits::destroy(m_name);
    m_name = 0;
  }

private:
  GLuint m_name = 0;
};

} // namespace rtlab::gl
