// Internal to framework/image: per-format encoders and decoders working on in-memory bytes.
// image_io.cpp reads and writes the files (atomically) and dispatches on the extension; the
// codecs never touch the file system, which keeps the error handling in one place.
#pragma once
#include "image/image.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rtlab::detail {

// Throws Error(Input): "cannot read image 'PATH': REASON".
[[noreturn]] void invalidImageFile(const std::string& path, const std::string& reason);

// The most pixels a PNG or EXR decoder allocates: 8192 x 8192, the largest frame rtlab renders
// (--size). Those formats state their size in a header that a few bytes of a file can set to any
// value, and the decoding libraries allocate it before they find the data missing; a larger
// image is Error(Input) before decoding (found by fuzzing, docs/testing.md "Fuzzing"). PFM needs
// no cap: its pixels are stored uncompressed, so the file's size bounds the allocation.
inline constexpr long long kMaxImagePixels = 8192LL * 8192LL;
// Error(Input) naming the path unless 0 < width, height and width * height <= kMaxImagePixels.
void checkImageSize(long long width, long long height, const std::string& path);

// Throws Error(Internal) unless width, height > 0, channels is 1 or 3, pixels.size() matches and
// mask is empty or holds one value per pixel. `path` only names the image in the message.
void validateImage(const Image& image, const std::string& path);

// Collapses a library message to one line (no newlines, no trailing spaces).
std::string oneLine(const std::string& text);

// PFM: little-endian on write; both endiannesses on read. `path` is used in error messages.
std::string encodePfm(const Image& image);
Image decodePfm(const std::string& bytes, const std::string& path);

// EXR: 32-bit float channels (A,)B,G,R or (A,)Y, zip-compressed (lossless).
std::string encodeExr(const Image& image, const std::string& path);
Image decodeExr(const std::string& bytes, const std::string& path);

// PNG: 8-bit gray or RGB. pngBytes does the float -> byte mapping of PngEncoding (one byte per
// channel value, rows top to bottom); encodePng compresses it.
std::vector<std::uint8_t> pngBytes(const Image& image, PngEncoding encoding);
std::string encodePng(const Image& image, PngEncoding encoding, const std::string& path);
Image decodePng(const std::string& bytes, const std::string& path);

// The sRGB opto-electronic transfer function (linear [0,1] -> encoded [0,1]).
float srgbEncode(float linear);

} // namespace rtlab::detail
