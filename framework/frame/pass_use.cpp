#include "frame/pass_use.h"

namespace rtlab {

bool isTextureDesc(const ResourceDesc& d) { return std::holds_alternative<gl::TextureDesc>(d); }

std::string descDifference(const ResourceDesc& a, const ResourceDesc& b) {
  if (isTextureDesc(a) != isTextureDesc(b)) return isTextureDesc(a) ? "texture vs buffer" : "buffer vs texture";
  if (isTextureDesc(a)) return gl::descDifference(std::get<gl::TextureDesc>(a), std::get<gl::TextureDesc>(b));
  const auto& x = std::get<gl::BufferDesc>(a);
  const auto& y = std::get<gl::BufferDesc>(b);
  if (x.kind != y.kind) return std::string("kind ") + gl::bufferKindName(x.kind) + " vs " + gl::bufferKindName(y.kind);
  if (x.bytes != y.bytes) return "bytes " + std::to_string(x.bytes) + " vs " + std::to_string(y.bytes);
  return "";
}

GLbitfield barrierBitFor(UseKind kind, bool texture) {
  switch (kind) {
  case UseKind::Sampled: return GL_TEXTURE_FETCH_BARRIER_BIT;
  case UseKind::Attachment: return GL_FRAMEBUFFER_BARRIER_BIT;
  case UseKind::Image: return GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;
  case UseKind::StorageBuffer: return GL_SHADER_STORAGE_BARRIER_BIT;
  case UseKind::AtomicCounter: return GL_ATOMIC_COUNTER_BARRIER_BIT;
  case UseKind::Indirect: return GL_COMMAND_BARRIER_BIT;
  case UseKind::ReadBack: return texture ? GL_TEXTURE_UPDATE_BARRIER_BIT : GL_BUFFER_UPDATE_BARRIER_BIT;
  }
  return 0;
}

std::string barrierBitsName(GLbitfield bits) {
  static const std::pair<GLbitfield, const char*> kNames[] = {
      {GL_TEXTURE_FETCH_BARRIER_BIT, "TEXTURE_FETCH"},   {GL_SHADER_IMAGE_ACCESS_BARRIER_BIT, "SHADER_IMAGE_ACCESS"},
      {GL_FRAMEBUFFER_BARRIER_BIT, "FRAMEBUFFER"},       {GL_SHADER_STORAGE_BARRIER_BIT, "SHADER_STORAGE"},
      {GL_ATOMIC_COUNTER_BARRIER_BIT, "ATOMIC_COUNTER"}, {GL_COMMAND_BARRIER_BIT, "COMMAND"},
      {GL_TEXTURE_UPDATE_BARRIER_BIT, "TEXTURE_UPDATE"}, {GL_BUFFER_UPDATE_BARRIER_BIT, "BUFFER_UPDATE"},
  };
  std::string out;
  for (const auto& [bit, name] : kNames)
    if (bits & bit) {
      if (!out.empty()) out += "|";
      out += name;
    }
  return out.empty() ? "0" : out;
}

const char* useKindName(UseKind kind) {
  switch (kind) {
  case UseKind::Sampled: return "sampled";
  case UseKind::Attachment: return "attachment";
  case UseKind::Image: return "image";
  case UseKind::StorageBuffer: return "storage buffer";
  case UseKind::AtomicCounter: return "atomic counter";
  case UseKind::Indirect: return "indirect";
  case UseKind::ReadBack: return "read-back";
  }
  return "sampled";
}

} // namespace rtlab
