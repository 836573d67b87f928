// Float images: the one in-memory format for AOVs, references and comparisons.
#pragma once
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace rtlab {

// Row-major, rows top to bottom, `channels` floats per pixel (1 or 3). `mask` is empty or holds
// one value per pixel: 1 on surface pixels, 0 on background (written as EXR channel A).
struct Image {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<float> pixels;
  std::vector<float> mask;

  Image() = default;
  Image(int w, int h, int c) : width(w), height(h), channels(c), pixels(std::size_t(w) * h * c, 0.0f) {}
  float& at(int x, int y, int c) { return pixels[(std::size_t(y) * width + x) * channels + c]; }
  float at(int x, int y, int c) const { return pixels[(std::size_t(y) * width + x) * channels + c]; }
  bool hasMask() const { return !mask.empty(); }
  std::size_t pixelCount() const { return std::size_t(width) * height; }
};

// The smallest and largest finite value over the valid pixels (mask > 0.5 where there is a mask)
// and every channel; empty() when there is none. (png_io.cpp: the depth preview's range.)
struct ValueRange {
  float min = std::numeric_limits<float>::infinity();
  float max = -std::numeric_limits<float>::infinity();
  bool empty() const { return !(min <= max); }
};
ValueRange validRange(const Image& image);

// How a PNG encodes an image (docs/contract.md "Images and AOVs").
enum class PngEncoding {
  Linear01,   // clamp to [0,1], linear (visibility, ao, albedo)
  Srgb,       // clamp to [0,1], sRGB transfer (already tone-mapped color)
  Normal,     // n*0.5+0.5
  NormalizeRange // map [min,max] over valid pixels to [0,1] (depth)
};

enum class ImageFormat { Png, Exr, Pfm };

// From the file extension (.png .exr .pfm, case-insensitive); throws Error(Usage) otherwise.
ImageFormat imageFormatFromPath(const std::string& path);
// An output image named by the user, checked before any work: a directory is Error(Output)
// naming it (not an unsupported format), then the extension (Error(Usage)), then the folder
// (util/atomic_file.h checkOutputPath: missing or not writable is Error(Output)).
ImageFormat checkImageOutputPath(const std::string& path);
// For outputs that are PNG only (the viewer's screenshots): Error(Usage) "<what> must be a .png
// file, got 'PATH'" unless the extension is .png (case-insensitive); a directory is Error(Output)
// naming it, as in checkImageOutputPath.
void requirePngPath(const std::string& path, const std::string& what);

// Writes atomically (util/atomic_file.h); throws Error(Output) naming the path on failure.
// PNG: 8-bit, 1 channel -> gray, 3 -> RGB. EXR: 32-bit float, channels Y or R,G,B, plus A from the
// mask when present. PFM: little-endian (scale -1), rows bottom-to-top, Pf (1 ch) or PF (3 ch).
void writeImage(const std::string& path, const Image& image, PngEncoding png = PngEncoding::Linear01);

// Reads PNG (as linear [0,1] values of the stored bytes, no sRGB decode), EXR (Y or RGB; A becomes
// the mask) and PFM. Throws Error(Input) naming the path when missing, unreadable or invalid.
Image readImage(const std::string& path);

// An 8-bit PNG file in memory (the same bytes writeImage would write), for images embedded in
// HTML reports as data: URIs. Throws Error(Internal) for an invalid image, Error(Output) if
// encoding fails. (framework/image/png_encode.cpp)
std::vector<unsigned char> encodePng(const Image& image, PngEncoding encoding = PngEncoding::Linear01);

} // namespace rtlab
