// OpenEXR through tinyexr (the 1.0.1 C API: Parse/Load/SaveEXRImage*Memory).
#include "image/image_io_internal.h"

#include "util/error.h"

#include <tinyexr.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>

namespace rtlab::detail {
namespace {

// Owns what tinyexr allocated while parsing and loading; frees it on every path.
struct LoadedExr {
  EXRHeader header;
  EXRImage image;
  bool imageLoaded = false;
  LoadedExr() {
    InitEXRHeader(&header);
    InitEXRImage(&image);
  }
  // The header is filled (allocated) even when parsing fails, so it is always freed. A failed
  // load frees the image itself without clearing its pointers, so only a loaded one is freed here.
  ~LoadedExr() {
    if (imageLoaded) FreeEXRImage(&image);
    FreeEXRHeader(&header);
  }
  LoadedExr(const LoadedExr&) = delete;
  LoadedExr& operator=(const LoadedExr&) = delete;
};

// Takes ownership of a tinyexr error message and returns it as one line.
std::string takeMessage(const char* err, int code) {
  std::string message = err ? oneLine(err) : "tinyexr error " + std::to_string(code);
  if (err) FreeEXRErrorMessage(err);
  return message;
}

int findChannel(const EXRHeader& header, const char* name) {
  for (int c = 0; c < header.num_channels; ++c)
    if (std::strcmp(header.channels[c].name, name) == 0) return c;
  return -1;
}

// One channel of the loaded image as floats (loaded as FLOAT when it was HALF, or UINT as is).
float channelValue(const LoadedExr& exr, int channel, std::size_t index) {
  const unsigned char* plane = exr.image.images[channel];
  if (exr.header.pixel_types[channel] == TINYEXR_PIXELTYPE_UINT) {
    unsigned int v;
    std::memcpy(&v, plane + index * 4, 4);
    return float(v);
  }
  float v;
  std::memcpy(&v, plane + index * 4, 4);
  return v;
}

} // namespace

std::string encodeExr(const Image& image, const std::string& path) {
  // OpenEXR wants the channel list sorted by name: A < B < G < R < Y.
  const std::size_t count = image.pixelCount();
  std::vector<std::string> names;
  std::vector<std::vector<float>> planes;
  if (image.hasMask()) {
    names.push_back("A");
    planes.push_back(image.mask);
  }
  const std::vector<std::pair<std::string, int>> colour =
      image.channels == 3 ? std::vector<std::pair<std::string, int>>{{"B", 2}, {"G", 1}, {"R", 0}}
                          : std::vector<std::pair<std::string, int>>{{"Y", 0}};
  for (const auto& [name, source] : colour) {
    std::vector<float> plane(count);
    for (std::size_t i = 0; i < count; ++i) plane[i] = image.pixels[i * image.channels + source];
    names.push_back(name);
    planes.push_back(std::move(plane));
  }

  const int n = int(planes.size());
  std::vector<EXRChannelInfo> infos(n);
  std::vector<int> pixelTypes(n, TINYEXR_PIXELTYPE_FLOAT);
  std::vector<int> storedTypes(n, TINYEXR_PIXELTYPE_FLOAT);
  std::vector<unsigned char*> pointers(n);
  for (int c = 0; c < n; ++c) {
    std::memset(&infos[c], 0, sizeof(EXRChannelInfo));
    std::strncpy(infos[c].name, names[c].c_str(), sizeof(infos[c].name) - 1);
    pointers[c] = reinterpret_cast<unsigned char*>(planes[c].data());
  }

  EXRHeader header;
  InitEXRHeader(&header);
  header.num_channels = n;
  header.channels = infos.data();
  header.pixel_types = pixelTypes.data();
  header.requested_pixel_types = storedTypes.data();
  header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;

  EXRImage exrImage;
  InitEXRImage(&exrImage);
  exrImage.images = pointers.data();
  exrImage.width = image.width;
  exrImage.height = image.height;
  exrImage.num_channels = n;

  unsigned char* memory = nullptr;
  const char* err = nullptr;
  const std::size_t size = SaveEXRImageToMemory(&exrImage, &header, &memory, &err);
  if (size == 0 || !memory) {
    const std::string reason = takeMessage(err, 0);
    std::free(memory);
    outputError("cannot write '" + path + "': EXR encoding failed: " + reason);
  }
  if (err) FreeEXRErrorMessage(err);
  std::string bytes(reinterpret_cast<const char*>(memory), size);
  std::free(memory);
  return bytes;
}

// Debian's tinyexr keeps its assert()s, and ParseEXRHeaderFromMemory asserts on a "type"
// attribute other than scanlineimage/tiledimage/deeptile/deepscanline or one that contradicts
// the version's tiled flag: a crafted file aborted rtlab (found by fuzzing, docs/testing.md
// "Fuzzing"). The single-part header's attributes (name, type name, int32 size, value) are
// therefore read here first, and a "type" other than a scanline image is rejected.
namespace {

void checkExrTypeAttribute(const std::string& bytes, const std::string& path) {
  std::size_t pos = 8; // magic and version
  auto cString = [&](const char* what) {
    const std::size_t end = bytes.find('\0', pos);
    if (end == std::string::npos) invalidImageFile(path, std::string("invalid EXR header: truncated ") + what);
    std::string text = bytes.substr(pos, end - pos);
    pos = end + 1;
    return text;
  };
  while (true) {
    const std::string name = cString("attribute name");
    if (name.empty()) return; // end of the header
    cString("attribute type");
    if (bytes.size() - pos < 4) invalidImageFile(path, "invalid EXR header: truncated attribute size");
    std::int32_t size = 0;
    std::memcpy(&size, bytes.data() + pos, 4); // little-endian, as the file
    pos += 4;
    if (size < 0 || std::size_t(size) > bytes.size() - pos)
      invalidImageFile(path, "invalid EXR header: attribute '" + name + "' runs past the end of the file");
    if (name == "type" && bytes.compare(pos, std::size_t(size), "scanlineimage") != 0)
      invalidImageFile(path, "only scanline EXR images are supported (type '" + bytes.substr(pos, std::min<std::size_t>(std::size_t(size), 40)) + "')");
    pos += std::size_t(size);
  }
}

} // namespace

Image decodeExr(const std::string& bytes, const std::string& path) {
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  EXRVersion version;
  if (ParseEXRVersionFromMemory(&version, data, bytes.size()) != TINYEXR_SUCCESS)
    invalidImageFile(path, "not an OpenEXR file");
  if (version.multipart || version.non_image) invalidImageFile(path, "multi-part and deep EXR files are not supported");
  if (version.tiled) invalidImageFile(path, "tiled EXR files are not supported");
  checkExrTypeAttribute(bytes, path);

  LoadedExr exr;
  const char* err = nullptr;
  int rc = ParseEXRHeaderFromMemory(&exr.header, &version, data, bytes.size(), &err);
  if (rc != TINYEXR_SUCCESS) invalidImageFile(path, "invalid EXR header: " + takeMessage(err, rc));
  if (exr.header.tiled) invalidImageFile(path, "tiled EXR files are not supported");
  for (int c = 0; c < exr.header.num_channels; ++c)
    if (exr.header.pixel_types[c] == TINYEXR_PIXELTYPE_HALF) exr.header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;

  // The data window before tinyexr allocates it (a huge window made it throw std::length_error).
  const EXRBox2i& window = exr.header.data_window;
  checkImageSize(static_cast<long long>(window.max_x) - window.min_x + 1,
                 static_cast<long long>(window.max_y) - window.min_y + 1, path);

  // tinyexr 1.0.1 frees a half-decoded image itself but only frees as many planes as
  // image.num_channels says, which it sets after decoding; preset it so corrupt files do not leak.
  exr.image.num_channels = exr.header.num_channels;
  err = nullptr;
  try {
    rc = LoadEXRImageFromMemory(&exr.image, &exr.header, data, bytes.size(), &err);
  } catch (const std::exception&) { // std::length_error, std::bad_alloc: tinyexr sizes its tables from
                                      // other header fields too (the chunk count, the channels)
    invalidImageFile(path, "invalid EXR data: a table size in the file is out of range");
  }
  if (rc != TINYEXR_SUCCESS) invalidImageFile(path, "invalid EXR data: " + takeMessage(err, rc));
  exr.imageLoaded = true;
  if (!exr.image.images || exr.image.width <= 0 || exr.image.height <= 0)
    invalidImageFile(path, "EXR file holds no scanline image");

  // Colour channels: R,G,B, else Y, else the only channel that is not A, else a lone A.
  std::vector<int> sources;
  int alpha = findChannel(exr.header, "A");
  const int r = findChannel(exr.header, "R"), g = findChannel(exr.header, "G"), b = findChannel(exr.header, "B");
  const int y = findChannel(exr.header, "Y");
  if (r >= 0 && g >= 0 && b >= 0) {
    sources = {r, g, b};
  } else if (y >= 0) {
    sources = {y};
  } else if (exr.header.num_channels == 1) {
    sources = {0};
    alpha = -1;
  } else if (exr.header.num_channels == 2 && alpha >= 0) {
    sources = {alpha == 0 ? 1 : 0};
  } else {
    invalidImageFile(path, "EXR file has no R,G,B or Y channel");
  }

  Image image(exr.image.width, exr.image.height, int(sources.size()));
  const std::size_t count = image.pixelCount();
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t c = 0; c < sources.size(); ++c)
      image.pixels[i * sources.size() + c] = channelValue(exr, sources[c], i);
  if (alpha >= 0) {
    image.mask.resize(count);
    for (std::size_t i = 0; i < count; ++i) image.mask[i] = channelValue(exr, alpha, i);
  }
  return image;
}

} // namespace rtlab::detail
