// PassBuilder, ComputeGrid and PassContext (declared in frame/frame_graph.h; docs/frame-graph.md).
#include "frame/frame_graph.h"

#include "frame/resource_pool.h"
#include "util/error.h"

namespace rtlab {

// ---- PassBuilder ----

namespace {
PassUse makeUse(const std::string& resource, UseKind kind, Access access, int binding = -1, int level = 0, int layer = -1) {
  PassUse u;
  u.resource = resource;
  u.kind = kind;
  u.access = access;
  u.binding = binding;
  u.level = level;
  u.layer = layer;
  return u;
}
PassUse described(PassUse u, const ResourceDesc& desc) {
  u.hasDesc = true;
  u.desc = desc;
  return u;
}
UseKind bufferKind(BufferBinding b) { return b == BufferBinding::Storage ? UseKind::StorageBuffer : UseKind::AtomicCounter; }
} // namespace

void PassBuilder::add(PassUse use) { m_uses.push_back(std::move(use)); }

void PassBuilder::read(const std::string& r) { add(makeUse(r, UseKind::Sampled, Access::Read)); }

void PassBuilder::readIfPresent(const std::string& r) {
  PassUse u = makeUse(r, UseKind::Sampled, Access::Read);
  u.optional = true;
  add(u);
}

void PassBuilder::write(const std::string& r, const gl::TextureDesc& desc) { writeAttachment(r, desc, 0, -1); }

void PassBuilder::writeAttachment(const std::string& r, const gl::TextureDesc& desc, int level, int layer) {
  add(described(makeUse(r, UseKind::Attachment, Access::Write, -1, level, layer), desc));
}

void PassBuilder::readImage(const std::string& r, int unit, int level) {
  add(makeUse(r, UseKind::Image, Access::Read, unit, level));
}

void PassBuilder::writeImage(const std::string& r, const gl::TextureDesc& desc, int unit, int level) {
  add(described(makeUse(r, UseKind::Image, Access::Write, unit, level), desc));
}

void PassBuilder::readWriteImage(const std::string& r, int unit, int level) {
  add(makeUse(r, UseKind::Image, Access::ReadWrite, unit, level));
}

void PassBuilder::readBuffer(const std::string& r, BufferBinding binding, int index) {
  add(makeUse(r, bufferKind(binding), Access::Read, index));
}

void PassBuilder::writeBuffer(const std::string& r, const gl::BufferDesc& desc, BufferBinding binding, int index) {
  add(described(makeUse(r, bufferKind(binding), Access::Write, index), desc));
}

void PassBuilder::readWriteBuffer(const std::string& r, BufferBinding binding, int index) {
  add(makeUse(r, bufferKind(binding), Access::ReadWrite, index));
}

void PassBuilder::readIndirect(const std::string& r) { add(makeUse(r, UseKind::Indirect, Access::Read)); }
void PassBuilder::readBack(const std::string& r) { add(makeUse(r, UseKind::ReadBack, Access::Read)); }

const PassUse* PassBuilder::attachment(const std::string& r) const {
  for (const auto& u : m_uses)
    if (u.kind == UseKind::Attachment && u.resource == r) return &u;
  return nullptr;
}

// ---- ComputeGrid ----

ComputeGrid ComputeGrid::frame() { return ComputeGrid{}; }

ComputeGrid ComputeGrid::of(const std::string& resource, int level) {
  ComputeGrid g;
  g.source = Source::Resource;
  g.resource = resource;
  g.level = level;
  return g;
}

ComputeGrid ComputeGrid::fixed(glm::ivec3 invocations) {
  ComputeGrid g;
  g.source = Source::Fixed;
  g.size = invocations;
  return g;
}

ComputeGrid ComputeGrid::indirect(const std::string& buffer, std::size_t offset) {
  ComputeGrid g;
  g.source = Source::Indirect;
  g.resource = buffer;
  g.offset = offset;
  return g;
}

// ---- PassContext ----

bool PassContext::has(const std::string& resource) const {
  if (pass && pass->m_absent.count(resource)) return false;
  return pool.has(resource);
}

gl::Texture& PassContext::texture(const std::string& resource) const {
  gl::Texture* t = pool.find(resource);
  if (!t) throw Error(ExitCode::Internal, "frame resource '" + resource + "' was not produced this frame");
  return *t;
}

gl::BufferObject& PassContext::buffer(const std::string& resource) const {
  gl::BufferObject* b = pool.findBuffer(resource);
  if (!b) throw Error(ExitCode::Internal, "frame buffer '" + resource + "' was not produced this frame");
  return *b;
}

const gl::Framebuffer& PassContext::framebuffer(const std::string& label, const std::vector<std::string>& colors,
                                               const std::string& depth, int layer) const {
  auto attachmentOf = [&](const std::string& name) {
    gl::Attachment a{&texture(name), 0, -1};
    if (const PassUse* u = pass ? pass->attachment(name) : nullptr) {
      a.level = u->level;
      a.layer = u->layer;
    }
    return a;
  };
  std::vector<gl::Attachment> attachments;
  for (const auto& c : colors) attachments.push_back(attachmentOf(c));
  gl::Attachment d;
  if (!depth.empty()) {
    d = attachmentOf(depth);
    if (layer >= 0) d.layer = layer;
  }
  return pool.framebuffer(label, attachments, d);
}

void PassContext::beginFullscreen(const std::string& label, const std::vector<std::string>& colors) const {
  const gl::Framebuffer& fbo = framebuffer(label, colors);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  const PassUse* u = pass ? pass->attachment(colors.front()) : nullptr;
  const int level = u ? u->level : 0;
  const gl::TextureDesc& d = texture(colors.front()).desc();
  glViewport(0, 0, d.widthAt(level), d.heightAt(level));
}

} // namespace rtlab
