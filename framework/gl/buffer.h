// An owned, immutable-storage buffer object (glNamedBufferStorage) with the description it was made
// from, so that the frame's resource pool can reuse it and stats can count its bytes: the storage,
// atomic-counter and indirect-argument buffers of docs/frame-graph.md.
#pragma once
#include "gl/objects.h"

#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

namespace rtlab::gl {

// What a buffer is made for. The kind names the buffer's role in labels and stats; any buffer can be
// bound at any of the three binding points.
enum class BufferKind { Storage, AtomicCounter, Indirect };
const char* bufferKindName(BufferKind kind); // "storage", "atomic counter", "indirect"

struct BufferDesc {
  BufferKind kind = BufferKind::Storage;
  std::size_t bytes = 0;
  bool operator==(const BufferDesc& o) const { return kind == o.kind && bytes == o.bytes; }
  bool operator!=(const BufferDesc& o) const { return !(*this == o); }
};

class BufferObject {
public:
  BufferObject() = default;
  // Allocates `desc.bytes`, updatable with glNamedBufferSubData and readable back, holding `initial`
  // (desc.bytes bytes) or zeros.
  BufferObject(const BufferDesc& desc, const std::string& label, const void* initial = nullptr);

  GLuint id() const { return m_buffer.id(); }
  const BufferDesc& desc() const { return m_desc; }
  explicit operator bool() const { return bool(m_buffer); }

  // Sets every byte to zero (an atomic counter's reset, an append buffer's emptying).
  void clear() const;
  void upload(const void* data, std::size_t bytes, std::size_t offset = 0) const;
  // Copies the buffer back to the CPU (waits for the GPU).
  std::vector<unsigned char> download() const;
  template <typename T>
  std::vector<T> downloadAs() const {
    const std::vector<unsigned char> raw = download();
    std::vector<T> out(raw.size() / sizeof(T));
    if (!out.empty()) std::memcpy(out.data(), raw.data(), out.size() * sizeof(T));
    return out;
  }

private:
  Buffer m_buffer;
  BufferDesc m_desc;
};

} // namespace rtlab::gl
