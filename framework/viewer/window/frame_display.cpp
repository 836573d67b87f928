#include "viewer/window/frame_display.h"

#include <algorithm>
#include <vector>

namespace rtlab {

void FrameDisplay::draw(const DisplayRequest& r) {
  if (!r.a.texture) return;
  gl::Program& program = m_programs.get({{"common/fullscreen.vert", "viewer/display.frag"}, {}, "viewer.display"});
  const DisplaySide& b = r.b.texture ? r.b : r.a;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(r.x, r.y, r.width, r.height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_CULL_FACE);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  program.use();
  r.a.texture->bind(0);
  b.texture->bind(1);
  program.set("uA", 0)
      .set("uB", 1)
      .set("uKindA", int(r.a.kind))
      .set("uKindB", int(b.kind))
      .set("uChannelsA", r.a.channels)
      .set("uChannelsB", b.channels)
      .set("uMin", r.min)
      .set("uMax", r.max)
      .set("uFalseColor", r.falseColor)
      .set("uMode", r.mode == DisplayRequest::Ramp || r.b.texture ? int(r.mode) : 0)
      .set("uDivider", r.divider)
      .set("uDividerPx", 1.0f / float(std::max(r.width, 1)));
  m_common.drawFullscreen();
}

gl::Texture copyTexture(const gl::Texture& source, const std::string& label) {
  gl::TextureDesc desc = source.desc();
  desc.levels = 1;
  gl::Texture copy(desc, label);
  glCopyImageSubData(source.id(), GL_TEXTURE_2D, 0, 0, 0, 0, copy.id(), GL_TEXTURE_2D, 0, 0, 0, 0, desc.width,
                     desc.height, 1);
  return copy;
}

void uploadImage(const Image& image, gl::Texture& texture, const std::string& label) {
  if (!texture || texture.desc().width != image.width || texture.desc().height != image.height) {
    gl::TextureDesc desc;
    desc.format = GL_RGBA32F;
    desc.width = image.width;
    desc.height = image.height;
    texture = gl::Texture(desc, label);
  }
  std::vector<float> rgba(std::size_t(image.width) * image.height * 4);
  for (int y = 0; y < image.height; ++y) {
    const int row = image.height - 1 - y; // GL rows are bottom to top
    for (int x = 0; x < image.width; ++x) {
      float* dst = &rgba[(std::size_t(row) * image.width + x) * 4];
      for (int c = 0; c < 3; ++c)
        dst[c] = image.at(x, y, image.channels == 1 ? 0 : c);
      dst[3] = image.mask.empty() ? 1.0f : image.mask[std::size_t(y) * image.width + x];
    }
  }
  glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_FLOAT, rgba.data());
}

} // namespace rtlab
