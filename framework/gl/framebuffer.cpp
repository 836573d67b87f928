#include "gl/framebuffer.h"

#include "util/error.h"

#include <cstdio>

namespace rtlab::gl {
namespace {

void attach(GLuint fbo, GLenum point, const Attachment& a, const std::string& label) {
  const TextureDesc& d = a.texture->desc();
  if (a.level < 0 || a.level >= d.levels)
    throw Error(ExitCode::Internal, "framebuffer '" + label + "': level " + std::to_string(a.level) + " of a " +
                                        std::to_string(d.levels) + "-level texture");
  if (a.layer >= d.layersAt(a.level) || (a.layer >= 0 && !d.layered()))
    throw Error(ExitCode::Internal, "framebuffer '" + label + "': layer " + std::to_string(a.layer) + " of a " +
                                        targetName(d.target) + " texture with " + std::to_string(d.layersAt(a.level)) +
                                        " layers at level " + std::to_string(a.level));
  if (a.layer >= 0) glNamedFramebufferTextureLayer(fbo, point, a.texture->id(), a.level, a.layer);
  else glNamedFramebufferTexture(fbo, point, a.texture->id(), a.level);
}

} // namespace

Framebuffer makeFramebuffer(const std::string& label, const std::vector<Attachment>& colors, const Attachment& depth) {
  Framebuffer fbo(label);
  std::vector<GLenum> drawBuffers;
  GLenum point = GL_COLOR_ATTACHMENT0;
  for (const Attachment& c : colors) {
    attach(fbo.id(), point, c, label);
    drawBuffers.push_back(point++);
  }
  if (depth.texture) attach(fbo.id(), GL_DEPTH_ATTACHMENT, depth, label);
  if (drawBuffers.empty()) glNamedFramebufferDrawBuffer(fbo.id(), GL_NONE);
  else glNamedFramebufferDrawBuffers(fbo.id(), GLsizei(drawBuffers.size()), drawBuffers.data());
  const GLenum status = glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04X", unsigned(status));
    throw Error(ExitCode::Internal, "framebuffer '" + label + "' is incomplete (status " + hex + ")");
  }
  return fbo;
}

Framebuffer makeFramebuffer(const std::string& label, const std::vector<const Texture*>& colors, const Texture* depth,
                            int layer) {
  std::vector<Attachment> attachments;
  for (const Texture* c : colors) attachments.push_back(Attachment{c, 0, -1});
  return makeFramebuffer(label, attachments, Attachment{depth, 0, depth ? layer : -1});
}

} // namespace rtlab::gl
