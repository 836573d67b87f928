#include "viewer/window/screenshot.h"

#include "gl/gl.h"
#include "util/error.h"

#include <vector>

namespace rtlab {

Image readWindow(int width, int height) {
  std::vector<unsigned char> rgb(std::size_t(width) * height * 3);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  Image image(width, height, 3);
  for (int y = 0; y < height; ++y) {
    const unsigned char* row = &rgb[std::size_t(height - 1 - y) * width * 3]; // GL rows are bottom to top
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c)
        image.at(x, y, c) = float(row[x * 3 + c]) / 255.0f;
  }
  return image;
}

void writeScreenshot(const std::string& path, int width, int height) {
  // The command line and scripts check this before the window opens; the panel's path field and
  // F12 get here unchecked (writeImage would write display values into an .exr or .pfm).
  requirePngPath(path, "screenshot");
  // The values are already display-encoded: stored unchanged.
  writeImage(path, readWindow(width, height), PngEncoding::Linear01);
}

} // namespace rtlab
