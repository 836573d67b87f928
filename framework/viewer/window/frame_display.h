// Draws the viewer's picture into the window's framebuffer (shaders/viewer/display.frag): one
// image, a split-screen wipe of two, or the difference heat map of two; color images are shown
// tone-mapped, data (AOVs, debug views, the reference) through a value range, in gray or false
// color. Also the texture helpers the compare modes need (snapshot copies, CPU image uploads).
#pragma once
#include "gl/program_cache.h"
#include "gl/texture.h"
#include "image/image.h"
#include "shading/gpu_common.h"

namespace rtlab {

enum class DisplayKind { Color = 0, Data = 1 };

struct DisplaySide {
  const gl::Texture* texture = nullptr;
  DisplayKind kind = DisplayKind::Color;
  int channels = 3;
};

struct DisplayRequest {
  DisplaySide a, b; // b only for the wipe and the difference
  // Ramp: the colour scale itself, from the range's min (left) to its max (right), in gray or
  // false color: the bar that labels a data view (`a` is bound, not read).
  enum Mode { Single = 0, Wipe = 1, Difference = 2, Ramp = 3 } mode = Single;
  float min = 0.0f, max = 1.0f; // data range (and the difference's full scale: max - min)
  bool falseColor = false;
  float divider = 0.5f;
  int x = 0, y = 0, width = 1, height = 1; // window region, pixels, GL's lower-left origin
};

class FrameDisplay {
public:
  // The program is built in `programs` on first draw (hot-reloaded with the others).
  explicit FrameDisplay(gl::ProgramCache& programs) : m_programs(programs) {}
  void draw(const DisplayRequest& request);

private:
  gl::ProgramCache& m_programs;
  GpuCommon m_common;
};

// A copy of `source` (same size and format), for the "snapshot" compare mode.
gl::Texture copyTexture(const gl::Texture& source, const std::string& label);
// Uploads a CPU image (1 or 3 channels, rows top to bottom) into `texture` as RGBA32F, creating
// or resizing it as needed; alpha holds the mask (1 where there is none).
void uploadImage(const Image& image, gl::Texture& texture, const std::string& label);

} // namespace rtlab
