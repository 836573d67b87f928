// Screenshots of the viewer: the window's back buffer as drawn (picture and panel), read before
// the swap and written as PNG atomically (never a half-written file).
#pragma once
#include "image/image.h"

#include <string>

namespace rtlab {

// The default framebuffer's back buffer, rows top to bottom, 3 channels of display values.
Image readWindow(int width, int height);
// Writes readWindow() as PNG; Error(Usage) unless the path ends in .png, Error(Output) naming the
// path on failure.
void writeScreenshot(const std::string& path, int width, int height);

} // namespace rtlab
