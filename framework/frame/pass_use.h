// How a frame-graph pass uses one resource (docs/frame-graph.md "Use declarations"), and the memory
// barrier each use needs after an incoherent write (image store, storage buffer, atomic counter).
#pragma once
#include "gl/buffer.h"
#include "gl/texture.h"

#include <string>
#include <variant>

namespace rtlab {

// What a frame resource is: a texture or a buffer.
using ResourceDesc = std::variant<gl::TextureDesc, gl::BufferDesc>;
bool isTextureDesc(const ResourceDesc& desc);
// The first field in which two descriptions differ ("size 32x64 vs 64x64", "bytes 32 vs 16",
// "texture vs buffer"); "" when equal.
std::string descDifference(const ResourceDesc& a, const ResourceDesc& b);

enum class UseKind {
  Sampled,       // texture fetch through a sampler unit (the pass binds the texture itself)
  Attachment,    // framebuffer attachment at (level, layer)
  Image,         // glBindImageTexture at (unit, level)
  StorageBuffer, // glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding)
  AtomicCounter, // glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, binding)
  Indirect,      // GL_DRAW_INDIRECT_BUFFER and GL_DISPATCH_INDIRECT_BUFFER
  ReadBack,      // read on the CPU (glGetTextureImage, glGetNamedBufferSubData)
};
enum class Access { Read, Write, ReadWrite };
// The buffer binding points a pass can declare at an index.
enum class BufferBinding { Storage, AtomicCounter };

struct PassUse {
  std::string resource;
  UseKind kind = UseKind::Sampled;
  Access access = Access::Read;
  bool optional = false;           // readIfPresent: no error (and ctx.has() false) when no earlier pass writes it
  bool hasDesc = false;            // writes describe the resource
  ResourceDesc desc;
  int binding = -1;                // image unit or buffer binding index
  int level = 0;                   // image or attachment level
  int layer = -1;                  // attachment layer, -1 = all

  bool reads() const { return access != Access::Write; }
  bool writes() const { return access != Access::Read; }
  // Writes through image stores, storage buffers or atomic counters are not visible to later
  // commands without glMemoryBarrier; attachment writes are.
  bool writesIncoherently() const {
    return writes() && (kind == UseKind::Image || kind == UseKind::StorageBuffer || kind == UseKind::AtomicCounter);
  }
};

// The glMemoryBarrier bit that makes an earlier incoherent write visible to a use of this kind;
// `texture` tells a read-back of a texture (TEXTURE_UPDATE) from one of a buffer (BUFFER_UPDATE).
GLbitfield barrierBitFor(UseKind kind, bool texture);
// "TEXTURE_FETCH|SHADER_STORAGE" (for messages and docs); "0" for none.
std::string barrierBitsName(GLbitfield bits);
const char* useKindName(UseKind kind);

} // namespace rtlab
