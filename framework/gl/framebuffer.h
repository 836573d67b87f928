// Framebuffers over textures: which level and which layer of each texture is attached
// (docs/frame-graph.md "Attachments").
#pragma once
#include "gl/objects.h"
#include "gl/texture.h"

#include <string>
#include <vector>

namespace rtlab::gl {

// One attachment: mip `level` of `texture`, and either one layer (a 2D-array layer, a cube face
// 0..5 in +X -X +Y -Y +Z -Z order, or a 3D slice) or, with layer = -1, the whole level (layered
// rendering for array, cube and 3D textures; the level itself for a 2D texture).
struct Attachment {
  const Texture* texture = nullptr;
  int level = 0;
  int layer = -1;
};

// A framebuffer with color attachment i = colors[i] and the given depth attachment (none when its
// texture is null). Throws Error(Internal) naming the label when an attachment is out of range or
// GL reports the framebuffer incomplete.
Framebuffer makeFramebuffer(const std::string& label, const std::vector<Attachment>& colors,
                            const Attachment& depth = {});
// Level 0 of each texture; `layer` selects one layer of the depth texture (e.g. a cube face).
Framebuffer makeFramebuffer(const std::string& label, const std::vector<const Texture*>& colors,
                            const Texture* depth = nullptr, int layer = -1);

} // namespace rtlab::gl
