#include "gl/shader_overlay.h"

namespace rtlab::gl {
namespace {
ShaderOverlay& overlayStorage() {
  static ShaderOverlay overlay;
  return overlay;
}
} // namespace

void setShaderOverlay(ShaderOverlay overlay) { overlayStorage() = std::move(overlay); }
const ShaderOverlay& shaderOverlay() { return overlayStorage(); }

} // namespace rtlab::gl
