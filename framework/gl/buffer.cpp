#include "gl/buffer.h"

namespace rtlab::gl {

const char* bufferKindName(BufferKind kind) {
  switch (kind) {
  case BufferKind::Storage: return "storage";
  case BufferKind::AtomicCounter: return "atomic counter";
  case BufferKind::Indirect: return "indirect";
  }
  return "storage";
}

BufferObject::BufferObject(const BufferDesc& desc, const std::string& label, const void* initial)
    : m_buffer(label), m_desc(desc) {
  // The initial contents go in with the storage, from the CPU, never as a GPU clear: on NVIDIA's
  // driver (580, H100) a glNamedBufferSubData of 98 KB issued right after glClearNamedBufferData on
  // a new buffer was overtaken by the clear, and the buffer read back as zeros (llvmpipe keeps the
  // order). Zeros from the CPU cost one copy of the buffer when it is made (the pool reuses it).
  std::vector<unsigned char> zeros;
  if (!initial) zeros.resize(desc.bytes);
  glNamedBufferStorage(m_buffer.id(), GLsizeiptr(desc.bytes), initial ? initial : zeros.data(),
                       GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
}

void BufferObject::clear() const {
  const GLuint zero = 0;
  if (m_desc.bytes % 4 == 0) glClearNamedBufferData(m_buffer.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  else glClearNamedBufferData(m_buffer.id(), GL_R8UI, GL_RED_INTEGER, GL_UNSIGNED_BYTE, &zero);
}

void BufferObject::upload(const void* data, std::size_t bytes, std::size_t offset) const {
  glNamedBufferSubData(m_buffer.id(), GLintptr(offset), GLsizeiptr(bytes), data);
}

std::vector<unsigned char> BufferObject::download() const {
  std::vector<unsigned char> out(m_desc.bytes);
  if (!out.empty()) glGetNamedBufferSubData(m_buffer.id(), 0, GLsizeiptr(out.size()), out.data());
  return out;
}

} // namespace rtlab::gl
