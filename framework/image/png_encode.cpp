// PNG encoding to memory (image.h encodePng): the codec of png_io.cpp without a file.
#include "image/image.h"
#include "image/image_io_internal.h"

namespace rtlab {

std::vector<unsigned char> encodePng(const Image& image, PngEncoding encoding) {
  detail::validateImage(image, "<memory>");
  const std::string bytes = detail::encodePng(image, encoding, "<memory>");
  return std::vector<unsigned char>(bytes.begin(), bytes.end());
}

} // namespace rtlab
