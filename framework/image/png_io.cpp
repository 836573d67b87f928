// 8-bit PNG through stb_image / stb_image_write (implementations come from libstb).
//
// Float -> byte mapping per PngEncoding. Every encoding writes 0 for NaN and clamps +-Inf.
// NormalizeRange (depth previews):
//  - the range [min, max] is taken over every channel value of the valid pixels: pixels whose
//    mask is > 0.5 (all pixels when there is no mask), finite values only;
//  - background pixels (mask <= 0.5) are written as 0;
//  - valid pixels map (v - min) / (max - min) to [0, 1]; NaN -> 0, +Inf -> 1, -Inf -> 0;
//  - max == min (a flat image): valid pixels are written as 1 so the surface stays visible
//    against the black background;
//  - no finite valid value at all: the whole image is 0.
// Reading stb's global "flip vertically on load" flag is assumed off (rtlab never sets it).
#include "image/image_io_internal.h"

#include "util/error.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rtlab::detail {
namespace {

constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

// Maps an encoded value in [0,1] (NaN -> 0, outside clamped) to a byte.
std::uint8_t toByte(float v) {
  if (std::isnan(v)) return 0;
  v = std::clamp(v, 0.0f, 1.0f);
  return std::uint8_t(std::lround(v * 255.0f));
}

bool isValidPixel(const Image& image, std::size_t pixel) {
  return image.mask.empty() || image.mask[pixel] > 0.5f;
}

void normalizeRange(const Image& image, std::vector<std::uint8_t>& out) {
  const ValueRange range = validRange(image);
  const std::size_t count = image.pixelCount();
  const int channels = image.channels;
  if (range.empty()) {
    std::fill(out.begin(), out.end(), std::uint8_t(0));
    return;
  }
  const double extent = double(range.max) - double(range.min);
  for (std::size_t p = 0; p < count; ++p) {
    const bool valid = isValidPixel(image, p);
    for (int c = 0; c < channels; ++c) {
      const std::size_t i = p * channels + c;
      const float v = image.pixels[i];
      if (!valid || std::isnan(v)) out[i] = 0;
      else if (extent <= 0.0) out[i] = 255;
      else out[i] = toByte(float((double(v) - range.min) / extent)); // +-Inf clamp in toByte
    }
  }
}

// stb_image trusts each chunk's length: an IDAT chunk claiming 2 GiB in a 100-byte file makes it
// allocate 2 GiB before it finds the data missing (found by fuzzing, docs/testing.md "Fuzzing").
// Every chunk up to IEND must therefore lie inside the file: length (4 bytes, big-endian), type,
// data, CRC.
void checkPngChunks(const std::string& bytes, const std::string& path) {
  std::size_t pos = sizeof(kPngSignature);
  while (pos < bytes.size()) {
    if (bytes.size() - pos < 12) invalidImageFile(path, "invalid PNG: truncated chunk at byte " + std::to_string(pos));
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data() + pos);
    const std::size_t length = std::size_t(p[0]) << 24 | std::size_t(p[1]) << 16 | std::size_t(p[2]) << 8 | p[3];
    if (length > bytes.size() - pos - 12)
      invalidImageFile(path, "invalid PNG: the chunk at byte " + std::to_string(pos) + " claims " +
                                 std::to_string(length) + " bytes, past the end of the file");
    const bool end = std::equal(p + 4, p + 8, "IEND");
    pos += 12 + length;
    if (end) break;
  }
}

[[noreturn]] void stbFailure(const std::string& path) {
  const char* reason = stbi_failure_reason();
  invalidImageFile(path, "invalid PNG: " + oneLine(reason ? reason : "decoder failed"));
}

void appendBytes(void* context, void* data, int size) {
  auto* out = static_cast<std::string*>(context);
  out->append(static_cast<const char*>(data), std::size_t(size));
}

} // namespace

float srgbEncode(float linear) {
  if (linear <= 0.0031308f) return 12.92f * linear;
  return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

std::vector<std::uint8_t> pngBytes(const Image& image, PngEncoding encoding) {
  std::vector<std::uint8_t> out(image.pixels.size());
  switch (encoding) {
  case PngEncoding::Linear01:
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = toByte(image.pixels[i]);
    break;
  case PngEncoding::Srgb:
    for (std::size_t i = 0; i < out.size(); ++i) {
      const float v = image.pixels[i];
      out[i] = std::isnan(v) ? 0 : toByte(srgbEncode(std::clamp(v, 0.0f, 1.0f)));
    }
    break;
  case PngEncoding::Normal:
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = toByte(image.pixels[i] * 0.5f + 0.5f);
    break;
  case PngEncoding::NormalizeRange:
    normalizeRange(image, out);
    break;
  }
  return out;
}

std::string encodePng(const Image& image, PngEncoding encoding, const std::string& path) {
  const std::vector<std::uint8_t> bytes = pngBytes(image, encoding);
  std::string out;
  const int stride = image.width * image.channels;
  if (!stbi_write_png_to_func(appendBytes, &out, image.width, image.height, image.channels, bytes.data(), stride))
    outputError("cannot write '" + path + "': PNG encoding failed");
  return out;
}

Image decodePng(const std::string& bytes, const std::string& path) {
  if (bytes.size() < sizeof(kPngSignature) || !std::equal(std::begin(kPngSignature), std::end(kPngSignature),
                                                          reinterpret_cast<const unsigned char*>(bytes.data())))
    invalidImageFile(path, "not a PNG file");
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int size = int(std::min<std::size_t>(bytes.size(), std::size_t(std::numeric_limits<int>::max())));
  checkPngChunks(bytes, path);
  int w = 0, h = 0, fileChannels = 0;
  if (!stbi_info_from_memory(data, size, &w, &h, &fileChannels))
    stbFailure(path);
  checkImageSize(w, h, path);
  // Gray and gray+alpha -> 1 channel; RGB, RGBA and palette -> 3 channels. Alpha is dropped.
  const int channels = fileChannels <= 2 ? 1 : 3;
  const bool sixteen = stbi_is_16_bit_from_memory(data, size) != 0;

  Image image;
  int loadedW = 0, loadedH = 0, ignored = 0;
  if (sixteen) {
    stbi_us* pixels = stbi_load_16_from_memory(data, size, &loadedW, &loadedH, &ignored, channels);
    if (!pixels) stbFailure(path);
    image = Image(loadedW, loadedH, channels);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = float(pixels[i]) / 65535.0f;
    stbi_image_free(pixels);
  } else {
    stbi_uc* pixels = stbi_load_from_memory(data, size, &loadedW, &loadedH, &ignored, channels);
    if (!pixels) stbFailure(path);
    image = Image(loadedW, loadedH, channels);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = float(pixels[i]) / 255.0f;
    stbi_image_free(pixels);
  }
  return image;
}

} // namespace rtlab::detail

namespace rtlab {

ValueRange validRange(const Image& image) {
  ValueRange range;
  for (std::size_t p = 0; p < image.pixelCount(); ++p) {
    if (!detail::isValidPixel(image, p)) continue;
    for (int c = 0; c < image.channels; ++c) {
      const float v = image.pixels[p * std::size_t(image.channels) + std::size_t(c)];
      if (!std::isfinite(v)) continue;
      range.min = std::min(range.min, v);
      range.max = std::max(range.max, v);
    }
  }
  return range;
}

} // namespace rtlab
