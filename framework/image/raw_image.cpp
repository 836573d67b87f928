#include "image/raw_image.h"

#include <cstring>
#include <stdexcept>

namespace rtlab {
namespace {

struct Shape {
  int width, height, channels;
  bool mask;
};

Shape parseShape(const nlohmann::json& shape) {
  if (!shape.is_array() || shape.size() != 4 || !shape[0].is_number_integer() || !shape[1].is_number_integer() ||
      !shape[2].is_number_integer() || !shape[3].is_boolean())
    throw std::invalid_argument("an image shape is [width, height, channels, mask]");
  const long long w = shape[0].get<long long>(), h = shape[1].get<long long>(), c = shape[2].get<long long>();
  if (w < 1 || w > 65536 || h < 1 || h > 65536 || c < 1 || c > 4)
    throw std::invalid_argument("image shape out of range: " + shape.dump());
  return Shape{int(w), int(h), int(c), shape[3].get<bool>()};
}

} // namespace

nlohmann::json rawImageShape(const Image& image) {
  return nlohmann::json::array({image.width, image.height, image.channels, image.hasMask()});
}

std::size_t rawImageBytes(const nlohmann::json& shape) {
  const Shape s = parseShape(shape);
  const std::size_t pixels = std::size_t(s.width) * std::size_t(s.height);
  return (pixels * std::size_t(s.channels) + (s.mask ? pixels : 0)) * sizeof(float);
}

void appendRawImage(std::string& out, const Image& image) {
  out.append(reinterpret_cast<const char*>(image.pixels.data()), image.pixels.size() * sizeof(float));
  if (image.hasMask()) out.append(reinterpret_cast<const char*>(image.mask.data()), image.mask.size() * sizeof(float));
}

Image rawImageFrom(const nlohmann::json& shape, const char* bytes) {
  const Shape s = parseShape(shape);
  Image image(s.width, s.height, s.channels);
  std::memcpy(image.pixels.data(), bytes, image.pixels.size() * sizeof(float));
  if (s.mask) {
    image.mask.resize(image.pixelCount());
    std::memcpy(image.mask.data(), bytes + image.pixels.size() * sizeof(float), image.mask.size() * sizeof(float));
  }
  return image;
}

} // namespace rtlab
