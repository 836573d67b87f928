// image/: PFM, EXR and PNG round trips, PNG encodings, and the exit codes of every failure.
#include "image/image.h"
#include "image/image_io_internal.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include "test_util.h"
#include <stb_image_write.h>
#include <tinyexr.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace rtlab;

namespace {

fs::path freshDir() { return rtlab::test::freshTestDir("image_io"); }
using rtlab::test::slurp;
std::set<std::string> entries(const fs::path& dir) { return rtlab::test::dirEntries(dir); }

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();



void writeRaw(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), std::streamsize(bytes.size()));
}

std::string readRaw(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Runs fn and returns the code of the Error it throws (Ok if none); checks the message is one
// line naming `mentions`.
ExitCode codeOf(const std::function<void()>& fn, const std::string& mentions = "") {
  try {
    fn();
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    if (!mentions.empty()) {
      EXPECT_NE(message.find(mentions), std::string::npos) << message;
    }
    return e.code();
  }
  return ExitCode::Ok;
}

// 3x2 RGB image with negatives, large, tiny and infinite values, distinct per pixel and channel.
Image sampleRgb() {
  Image image(3, 2, 3);
  const float values[] = {0.0f, -1.5f, 3.25e30f, 1e-30f, -0.0f, 42.125f, 0.1f, 0.2f, 0.3f,
                          -7.75f, 65504.5f, 1.0f / 3.0f, kInf, -kInf, 123456.789f, 2.0f, -2.0f, 0.5f};
  std::copy(std::begin(values), std::end(values), image.pixels.begin());
  return image;
}

void expectBitwiseEqual(const std::vector<float>& a, const std::vector<float>& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0);
}

float srgbReference(float v) { return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f; }

} // namespace

// ---- PFM ----

TEST(ImageRange, OverValidFinitePixelsAndEveryChannel) {
  // The depth preview's and the viewer's auto range: background (mask 0) and non-finite values
  // do not count; every channel does.
  Image im(3, 1, 2);
  im.pixels = {0.5f, -2.0f, 100.0f, 100.0f, std::numeric_limits<float>::infinity(), 3.0f};
  im.mask = {1.0f, 0.0f, 1.0f};
  const ValueRange r = validRange(im);
  EXPECT_EQ(r.min, -2.0f);
  EXPECT_EQ(r.max, 3.0f);
  im.mask = {0.0f, 0.0f, 0.0f};
  EXPECT_TRUE(validRange(im).empty());
}

TEST(PfmIo, RoundTripsThreeChannelsExactly) {
  const fs::path path = freshDir() / "rgb.pfm";
  const Image image = sampleRgb();
  writeImage(path.string(), image);
  EXPECT_EQ(readRaw(path).substr(0, 12), "PF\n3 2\n-1.0\n");
  const Image back = readImage(path.string());
  EXPECT_TRUE(back.width == 3 && back.height == 2 && back.channels == 3 && !back.hasMask());
  expectBitwiseEqual(back.pixels, image.pixels);
}

TEST(PfmIo, RoundTripsOneChannelAsPf) {
  const fs::path path = freshDir() / "depth.pfm";
  Image image(2, 3, 1);
  image.pixels = {-1.0f, 1e20f, 0.25f, 7.0f, -3e-5f, 1024.0f};
  writeImage(path.string(), image);
  EXPECT_EQ(readRaw(path).substr(0, 3), "Pf\n");
  const Image back = readImage(path.string());
  EXPECT_EQ(back.channels, 1);
  expectBitwiseEqual(back.pixels, image.pixels);
}

TEST(PfmIo, TopLeftStaysTopLeftAndFileStartsWithBottomRow) {
  const fs::path path = freshDir() / "corner.pfm";
  Image image(2, 2, 1);
  image.at(0, 0, 0) = 1.0f; // top-left
  image.at(1, 1, 0) = 4.0f; // bottom-right
  writeImage(path.string(), image);
  const std::string raw = readRaw(path);
  const std::string header = "Pf\n2 2\n-1.0\n";
  float firstStored = 0.0f; // the file's first value is the bottom-left pixel
  std::memcpy(&firstStored, raw.data() + header.size(), 4);
  EXPECT_EQ(firstStored, 0.0f);
  float lastRowFirst = 0.0f; // its last row is the top row
  std::memcpy(&lastRowFirst, raw.data() + header.size() + 8, 4);
  EXPECT_EQ(lastRowFirst, 1.0f);
  const Image back = readImage(path.string());
  EXPECT_TRUE(back.at(0, 0, 0) == 1.0f && back.at(1, 1, 0) == 4.0f && back.at(1, 0, 0) == 0.0f);
}

TEST(PfmIo, ReadsBigEndianFiles) {
  const fs::path path = freshDir() / "big.pfm";
  std::string bytes = "Pf\n2 1\n1.0\n";
  for (float v : {1.5f, -2.0f}) {
    std::uint32_t bits;
    std::memcpy(&bits, &v, 4);
    for (int shift = 24; shift >= 0; shift -= 8) bytes += char((bits >> shift) & 0xff);
  }
  writeRaw(path, bytes);
  const Image back = readImage(path.string());
  ASSERT_EQ(back.pixels.size(), 2u);
  EXPECT_EQ(back.pixels[0], 1.5f);
  EXPECT_EQ(back.pixels[1], -2.0f);
}

TEST(PfmIo, TruncatedFileIsInputError) {
  const fs::path path = freshDir() / "short.pfm";
  writeImage(path.string(), sampleRgb());
  const std::string raw = readRaw(path);
  writeRaw(path, raw.substr(0, raw.size() - 1));
  EXPECT_EQ(codeOf([&] { readImage(path.string()); }, path.string()), ExitCode::Input);
  writeRaw(path, "PF\n3 2\n-1.0\n");
  EXPECT_EQ(codeOf([&] { readImage(path.string()); }, path.string()), ExitCode::Input);
}

TEST(PfmIo, BadHeadersAreInputErrors) {
  const fs::path dir = freshDir();
  const std::string data(64, '\0');
  const std::vector<std::string> headers = {
      "P6\n2 2\n255\n",    "PX\n2 2\n-1.0\n", "PF\n0 2\n-1.0\n",  "PF\n2 -2\n-1.0\n", "PF\n2 2\n0\n",
      "PF\n2 2\nabc\n",    "PF\n2x2\n-1.0\n", "PF\n2 2\n-1.0",    "PF2 2\n-1.0\n",    "PF\n99999999999 1\n-1\n"};
  for (std::size_t i = 0; i < headers.size(); ++i) {
    const fs::path path = dir / ("bad" + std::to_string(i) + ".pfm");
    writeRaw(path, headers[i] + (i == 7 ? "" : data)); // #7: the header ends without data
    EXPECT_EQ(codeOf([&] { readImage(path.string()); }, path.string()), ExitCode::Input) << headers[i];
  }
}

// ---- EXR ----

TEST(ExrIo, RoundTripsRgbExactlyWithMask) {
  const fs::path path = freshDir() / "color.exr";
  Image image = sampleRgb();
  image.mask = {1, 0, 1, 1, 0, 1};
  writeImage(path.string(), image);
  const Image back = readImage(path.string());
  EXPECT_TRUE(back.width == 3 && back.height == 2 && back.channels == 3);
  expectBitwiseEqual(back.pixels, image.pixels);
  expectBitwiseEqual(back.mask, image.mask);
}

TEST(ExrIo, WritesFloatChannelsNamedByContract) {
  const fs::path path = freshDir() / "names.exr";
  Image image = sampleRgb();
  image.mask.assign(image.pixelCount(), 1.0f);
  writeImage(path.string(), image);
  const std::string raw = readRaw(path);
  const auto* data = reinterpret_cast<const unsigned char*>(raw.data());
  EXRVersion version;
  ASSERT_EQ(ParseEXRVersionFromMemory(&version, data, raw.size()), TINYEXR_SUCCESS);
  EXRHeader header;
  InitEXRHeader(&header);
  ASSERT_EQ(ParseEXRHeaderFromMemory(&header, &version, data, raw.size(), nullptr), TINYEXR_SUCCESS);
  std::set<std::string> names;
  for (int c = 0; c < header.num_channels; ++c) {
    names.insert(header.channels[c].name);
    EXPECT_EQ(header.pixel_types[c], TINYEXR_PIXELTYPE_FLOAT);
  }
  FreeEXRHeader(&header);
  EXPECT_EQ(names, (std::set<std::string>{"A", "B", "G", "R"}));
}

TEST(ExrIo, RoundTripsOneChannelAsY) {
  const fs::path path = freshDir() / "ao.exr";
  Image image(4, 1, 1);
  image.pixels = {0.0f, 0.25f, -9.5f, 1e25f};
  writeImage(path.string(), image);
  const std::string raw = readRaw(path);
  EXPECT_NE(raw.find(std::string("Y\0", 2)), std::string::npos);
  const Image back = readImage(path.string());
  EXPECT_TRUE(back.channels == 1 && !back.hasMask());
  expectBitwiseEqual(back.pixels, image.pixels);
}

TEST(ExrIo, ReadsHalfChannelsAndSingleChannelOfAnyName) {
  const fs::path path = freshDir() / "half.exr";
  std::vector<float> plane = {0.5f, 2.0f, -1.25f, 1024.0f};
  EXRChannelInfo info;
  std::memset(&info, 0, sizeof(info));
  std::strcpy(info.name, "Z");
  int inputType = TINYEXR_PIXELTYPE_FLOAT, storedType = TINYEXR_PIXELTYPE_HALF;
  EXRHeader header;
  InitEXRHeader(&header);
  header.num_channels = 1;
  header.channels = &info;
  header.pixel_types = &inputType;
  header.requested_pixel_types = &storedType;
  header.compression_type = TINYEXR_COMPRESSIONTYPE_NONE;
  unsigned char* planes[1] = {reinterpret_cast<unsigned char*>(plane.data())};
  EXRImage exr;
  InitEXRImage(&exr);
  exr.images = planes;
  exr.width = exr.height = 2;
  exr.num_channels = 1;
  ASSERT_EQ(SaveEXRImageToFile(&exr, &header, path.c_str(), nullptr), TINYEXR_SUCCESS);
  const Image back = readImage(path.string());
  EXPECT_TRUE(back.channels == 1 && back.width == 2 && back.height == 2);
  EXPECT_EQ(back.pixels, plane);
}

TEST(ExrIo, GarbageIsInputError) {
  const fs::path path = freshDir() / "garbage.exr";
  writeRaw(path, "this is not an OpenEXR file at all, just some words");
  EXPECT_EQ(codeOf([&] { readImage(path.string()); }, path.string()), ExitCode::Input);
  // A valid magic number followed by junk.
  writeRaw(path, std::string("\x76\x2f\x31\x01\x02\0\0\0", 8) + std::string(40, '\x7f'));
  EXPECT_EQ(codeOf([&] { readImage(path.string()); }, path.string()), ExitCode::Input);
  // A truncated real file.
  writeImage(path.string(), sampleRgb());
  const std::string raw = readRaw(path);
  writeRaw(path, raw.substr(0, raw.size() / 2));
  EXPECT_EQ(codeOf([&] { readImage(path.string()); }, path.string()), ExitCode::Input);
}

// ---- PNG ----

TEST(PngIo, Linear01StaysWithinOneStep) {
  const fs::path path = freshDir() / "linear.png";
  Image image(4, 2, 1);
  image.pixels = {0.0f, 0.1f, 0.5f, 1.0f, 1.5f, -0.2f, kNaN, kInf};
  writeImage(path.string(), image, PngEncoding::Linear01);
  const Image back = readImage(path.string());
  EXPECT_EQ(back.channels, 1);
  const float expected[] = {0.0f, 0.1f, 0.5f, 1.0f, 1.0f, 0.0f, 0.0f, 1.0f};
  for (int i = 0; i < 8; ++i) {
    EXPECT_NEAR(back.pixels[i], expected[i], 0.5f / 255.0f + 1e-6f) << i;
    EXPECT_FLOAT_EQ(back.pixels[i] * 255.0f, std::round(back.pixels[i] * 255.0f)) << i; // k/255
  }
}

TEST(PngIo, SrgbFollowsTheTransferFunction) {
  const fs::path path = freshDir() / "color.png";
  Image image(2, 2, 3);
  image.pixels = {0.0f, 0.001f, 0.0031308f, 0.01f, 0.18f, 0.2f, 0.5f, 0.73f, 0.9f, 1.0f, 2.0f, -1.0f};
  writeImage(path.string(), image, PngEncoding::Srgb);
  const Image back = readImage(path.string());
  ASSERT_EQ(back.channels, 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const float v = std::clamp(image.pixels[i], 0.0f, 1.0f);
    EXPECT_EQ(std::lround(back.pixels[i] * 255.0f), std::lround(srgbReference(v) * 255.0f)) << i;
  }
  EXPECT_NEAR(back.pixels[6], 188.0f / 255.0f, 1e-6f); // sRGB(0.5) = 0.7354 -> 188
}

TEST(PngIo, NormalMapsMinusOneToOne) {
  const fs::path path = freshDir() / "normal.png";
  Image image(2, 1, 3);
  image.pixels = {-1.0f, 0.0f, 1.0f, 0.5f, -0.5f, 3.0f};
  writeImage(path.string(), image, PngEncoding::Normal);
  const Image back = readImage(path.string());
  const int expected[] = {0, 128, 255, 191, 64, 255};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(std::lround(back.pixels[i] * 255.0f), expected[i]) << i;
}

TEST(PngIo, NormalizeRangeMapsValidMinAndMaxToZeroAndOne) {
  const fs::path path = freshDir() / "depth.png";
  Image image(3, 2, 1);
  image.pixels = {2.0f, 6.0f, 10.0f, 1000.0f, -5.0f, kNaN};
  image.mask = {1, 1, 1, 0, 0, 1}; // the outliers are background; NaN is a valid pixel
  writeImage(path.string(), image, PngEncoding::NormalizeRange);
  const Image back = readImage(path.string());
  EXPECT_EQ(back.pixels[0], 0.0f);
  EXPECT_EQ(back.pixels[2], 1.0f);
  EXPECT_NEAR(back.pixels[1], 0.5f, 1.0f / 255.0f);
  EXPECT_TRUE(back.pixels[3] == 0.0f && back.pixels[4] == 0.0f); // background
  EXPECT_EQ(back.pixels[5], 0.0f);                                 // NaN
}

TEST(PngIo, NormalizeRangeEdgeCases) {
  Image flat(2, 1, 1);
  flat.pixels = {3.0f, 3.0f};
  flat.mask = {1, 0};
  EXPECT_EQ(detail::pngBytes(flat, PngEncoding::NormalizeRange), (std::vector<std::uint8_t>{255, 0}));
  Image noMask(3, 1, 1);
  noMask.pixels = {-1.0f, kInf, 1.0f}; // infinities do not stretch the range but clamp
  EXPECT_EQ(detail::pngBytes(noMask, PngEncoding::NormalizeRange), (std::vector<std::uint8_t>{0, 255, 255}));
  Image allBackground(2, 1, 1);
  allBackground.pixels = {1.0f, 2.0f};
  allBackground.mask = {0, 0};
  EXPECT_EQ(detail::pngBytes(allBackground, PngEncoding::NormalizeRange), (std::vector<std::uint8_t>{0, 0}));
}

TEST(PngIo, ReadsAlphaAsDroppedChannel) {
  const fs::path dir = freshDir();
  const unsigned char rgba[] = {10, 20, 30, 40, 50, 60, 70, 80};
  ASSERT_NE(stbi_write_png((dir / "rgba.png").c_str(), 2, 1, 4, rgba, 8), 0);
  const Image rgb = readImage((dir / "rgba.png").string());
  EXPECT_TRUE(rgb.channels == 3 && !rgb.hasMask());
  EXPECT_EQ(std::lround(rgb.at(1, 0, 2) * 255.0f), 70);
  const unsigned char grayAlpha[] = {200, 1, 100, 2};
  ASSERT_NE(stbi_write_png((dir / "ga.png").c_str(), 2, 1, 2, grayAlpha, 4), 0);
  const Image gray = readImage((dir / "ga.png").string());
  EXPECT_EQ(gray.channels, 1);
  EXPECT_EQ(std::lround(gray.pixels[1] * 255.0f), 100);
}

TEST(PngIo, GarbageIsInputError) {
  const fs::path path = freshDir() / "garbage.png";
  writeRaw(path, "GIF89a and then nothing useful");
  EXPECT_EQ(codeOf([&] { readImage(path.string()); }, path.string()), ExitCode::Input);
  writeRaw(path, std::string("\x89PNG\r\n\x1a\n", 8) + std::string(30, 'x'));
  EXPECT_EQ(codeOf([&] { readImage(path.string()); }, path.string()), ExitCode::Input);
}

// ---- shared behaviour ----

TEST(ImageIo, MissingAndEmptyFilesAreInputErrors) {
  const fs::path dir = freshDir();
  for (const char* ext : {".png", ".exr", ".pfm"}) {
    const fs::path missing = dir / (std::string("missing") + ext);
    EXPECT_EQ(codeOf([&] { readImage(missing.string()); }, "cannot read image '" + missing.string() + "'"),
              ExitCode::Input);
    const fs::path empty = dir / (std::string("empty") + ext);
    writeRaw(empty, "");
    EXPECT_EQ(codeOf([&] { readImage(empty.string()); }, empty.string()), ExitCode::Input);
  }
  EXPECT_EQ(codeOf([&] { readImage(dir.string() + "/.pfm"); }), ExitCode::Input);
}

TEST(ImageIo, UnsupportedExtensionIsUsageError) {
  const fs::path dir = freshDir();
  const Image image(1, 1, 1);
  for (const std::string name : {"out.jpg", "out", "out.pfm.txt", "dir.png/out"}) {
    const std::string path = (dir / name).string();
    EXPECT_EQ(codeOf([&] { writeImage(path, image); }, "unsupported image format '" + path + "'"), ExitCode::Usage);
    EXPECT_EQ(codeOf([&] { readImage(path); }), ExitCode::Usage);
  }
  EXPECT_TRUE(entries(dir).empty());
  EXPECT_EQ(imageFormatFromPath("A.PNG"), ImageFormat::Png);
  EXPECT_EQ(imageFormatFromPath("dir.x/b.Exr"), ImageFormat::Exr);
  EXPECT_EQ(imageFormatFromPath("c.pFm"), ImageFormat::Pfm);
}

TEST(ImageIo, WritingIntoMissingDirectoryIsOutputError) {
  const fs::path dir = freshDir();
  for (const char* name : {"out.png", "out.exr", "out.pfm"}) {
    const std::string path = (dir / "missing" / name).string();
    EXPECT_EQ(codeOf([&] { writeImage(path, sampleRgb()); }, path), ExitCode::Output);
  }
  EXPECT_TRUE(entries(dir).empty());
}

TEST(ImageIo, FailedRenameLeavesNoTemporary) {
  const fs::path dir = freshDir();
  fs::create_directories(dir / "taken.exr");
  EXPECT_EQ(codeOf([&] { writeImage((dir / "taken.exr").string(), sampleRgb()); }), ExitCode::Output);
  EXPECT_EQ(entries(dir), std::set<std::string>{"taken.exr"});
}

TEST(ImageIo, InvalidImageIsInternalErrorAndWritesNothing) {
  const fs::path dir = freshDir();
  const std::string path = (dir / "bad.pfm").string();
  Image twoChannels(2, 2, 2);
  Image empty;
  Image shortPixels(2, 2, 3);
  shortPixels.pixels.pop_back();
  Image badMask(2, 2, 1);
  badMask.mask = {1, 0, 1};
  for (const Image* image : {&twoChannels, &empty, &shortPixels, &badMask})
    EXPECT_EQ(codeOf([&] { writeImage(path, *image); }), ExitCode::Internal);
  EXPECT_TRUE(entries(dir).empty());
}

TEST(ImageIo, OverwritesExistingFile) {
  const fs::path path = freshDir() / "twice.pfm";
  writeImage(path.string(), sampleRgb());
  Image small(1, 1, 1);
  small.pixels = {9.0f};
  writeImage(path.string(), small);
  const Image back = readImage(path.string());
  EXPECT_TRUE(back.width == 1 && back.pixels[0] == 9.0f);
}
