// Image files: format dispatch, validation, atomic writes and uniform read errors.
#include "image/image.h"
#include "image/image_io_internal.h"

#include "util/atomic_file.h"
#include "util/error.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace rtlab {
namespace detail {

void invalidImageFile(const std::string& path, const std::string& reason) {
  inputError("cannot read image '" + path + "': " + reason);
}

void checkImageSize(long long width, long long height, const std::string& path) {
  if (width <= 0 || height <= 0)
    invalidImageFile(path, "invalid size " + std::to_string(width) + "x" + std::to_string(height));
  if (width > kMaxImagePixels / height)
    invalidImageFile(path, "the image is " + std::to_string(width) + "x" + std::to_string(height) +
                               " pixels, more than the " + std::to_string(kMaxImagePixels) +
                               " (8192x8192) rtlab reads");
}

void validateImage(const Image& image, const std::string& path) {
  auto fail = [&](const std::string& what) {
    throw Error(ExitCode::Internal, "invalid image for '" + path + "': " + what);
  };
  if (image.width <= 0 || image.height <= 0)
    fail("size " + std::to_string(image.width) + "x" + std::to_string(image.height));
  if (image.channels != 1 && image.channels != 3)
    fail(std::to_string(image.channels) + " channels (must be 1 or 3)");
  const std::size_t count = image.pixelCount();
  if (image.pixels.size() != count * std::size_t(image.channels))
    fail("pixel buffer holds " + std::to_string(image.pixels.size()) + " values, expected " +
         std::to_string(count * std::size_t(image.channels)));
  if (!image.mask.empty() && image.mask.size() != count)
    fail("mask holds " + std::to_string(image.mask.size()) + " values, expected " + std::to_string(count));
}

std::string oneLine(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) out += (c == '\n' || c == '\r' || c == '\t') ? ' ' : c;
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out.empty() ? std::string("unknown error") : out;
}

} // namespace detail

namespace {

std::string lowerExtension(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// Reads the whole file; every failure (missing, a directory, unreadable, empty) is Error(Input).
std::string readImageBytes(const std::string& path) {
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) detail::invalidImageFile(path, errno ? std::strerror(errno) : "cannot open file");
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) detail::invalidImageFile(path, "read failed");
  // Opening a directory succeeds on Linux but reading it yields nothing (or fails).
  if (bytes.empty()) detail::invalidImageFile(path, "file is empty or not a regular file");
  return bytes;
}

} // namespace

ImageFormat imageFormatFromPath(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".png") return ImageFormat::Png;
  if (ext == ".exr") return ImageFormat::Exr;
  if (ext == ".pfm") return ImageFormat::Pfm;
  usageError("unsupported image format '" + path + "' (use .png, .exr or .pfm)");
}

ImageFormat checkImageOutputPath(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) checkOutputPath(path); // throws, naming the directory
  const ImageFormat format = imageFormatFromPath(path);
  checkOutputPath(path);
  return format;
}

void requirePngPath(const std::string& path, const std::string& what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) checkOutputPath(path); // throws, naming the directory
  if (lowerExtension(path) != ".png") usageError(what + " must be a .png file, got '" + path + "'");
}

void writeImage(const std::string& path, const Image& image, PngEncoding png) {
  const ImageFormat format = imageFormatFromPath(path);
  detail::validateImage(image, path);
  std::string bytes;
  switch (format) {
  case ImageFormat::Png: bytes = detail::encodePng(image, png, path); break;
  case ImageFormat::Exr: bytes = detail::encodeExr(image, path); break;
  case ImageFormat::Pfm: bytes = detail::encodePfm(image); break;
  }
  writeTextAtomically(path, bytes);
}

Image readImage(const std::string& path) {
  const ImageFormat format = imageFormatFromPath(path);
  const std::string bytes = readImageBytes(path);
  switch (format) {
  case ImageFormat::Png: return detail::decodePng(bytes, path);
  case ImageFormat::Exr: return detail::decodeExr(bytes, path);
  case ImageFormat::Pfm: return detail::decodePfm(bytes, path);
  }
  detail::invalidImageFile(path, "unknown format");
}

} // namespace rtlab
