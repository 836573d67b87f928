// Portable float map: "PF" (RGB) or "Pf" (gray), "W H", scale (negative: little-endian), then
// W*H*C 32-bit floats with rows stored bottom to top.
#include "image/image_io_internal.h"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>

namespace rtlab::detail {
namespace {

// Dimensions beyond this are certainly not an image of ours (and would overflow size arithmetic).
constexpr long long kMaxDimension = 1 << 20;

std::uint32_t byteSwap(std::uint32_t v) {
  return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

bool isSpace(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\v' || c == '\f'; }

// Walks the ASCII header; every failure names what was expected.
class HeaderReader {
public:
  HeaderReader(const std::string& bytes, const std::string& path) : m_bytes(bytes), m_path(path) {}

  void skipSpace() {
    const std::size_t start = m_pos;
    while (m_pos < m_bytes.size() && isSpace(m_bytes[m_pos])) ++m_pos;
    if (m_pos == start) fail("expected whitespace");
  }

  std::string_view token() {
    const std::size_t start = m_pos;
    while (m_pos < m_bytes.size() && !isSpace(m_bytes[m_pos]) && m_pos - start < 64) ++m_pos;
    if (m_pos == start) fail("unexpected end of header");
    return std::string_view(m_bytes).substr(start, m_pos - start);
  }

  long long dimension(const char* what) {
    const std::string_view t = token();
    long long value = 0;
    auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (ec != std::errc() || end != t.data() + t.size())
      fail(std::string("invalid ") + what + " '" + std::string(t) + "'");
    if (value <= 0 || value > kMaxDimension) fail(std::string("invalid ") + what + " " + std::to_string(value));
    return value;
  }

  double scale() {
    const std::string_view t = token();
    double value = 0.0;
    auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (ec != std::errc() || end != t.data() + t.size() || !std::isfinite(value) || value == 0.0)
      fail("invalid scale '" + std::string(t) + "'");
    return value;
  }

  // The header ends with exactly one whitespace character after the scale.
  void endOfHeader() {
    if (m_pos >= m_bytes.size() || !isSpace(m_bytes[m_pos])) fail("missing whitespace after the scale");
    ++m_pos;
  }

  std::size_t position() const { return m_pos; }
  [[noreturn]] void fail(const std::string& reason) const { invalidImageFile(m_path, "invalid PFM header: " + reason); }

private:
  const std::string& m_bytes;
  const std::string& m_path;
  std::size_t m_pos = 0;
};

} // namespace

std::string encodePfm(const Image& image) {
  const int w = image.width, h = image.height, c = image.channels;
  std::string out = std::string(c == 1 ? "Pf" : "PF") + "\n" + std::to_string(w) + " " + std::to_string(h) + "\n-1.0\n";
  const std::size_t headerSize = out.size();
  const std::size_t rowValues = std::size_t(w) * c;
  out.resize(headerSize + rowValues * h * 4);
  char* dst = out.data() + headerSize;
  for (int row = h - 1; row >= 0; --row) { // bottom row first
    const float* src = image.pixels.data() + std::size_t(row) * rowValues;
    for (std::size_t i = 0; i < rowValues; ++i, dst += 4) {
      std::uint32_t bits = std::bit_cast<std::uint32_t>(src[i]);
      if constexpr (std::endian::native == std::endian::big) bits = byteSwap(bits);
      std::memcpy(dst, &bits, 4);
    }
  }
  return out;
}

Image decodePfm(const std::string& bytes, const std::string& path) {
  HeaderReader reader(bytes, path);
  const std::string_view magic = reader.token();
  int channels = 0;
  if (magic == "PF") channels = 3;
  else if (magic == "Pf") channels = 1;
  else reader.fail("expected 'PF' or 'Pf'");
  reader.skipSpace();
  const long long width = reader.dimension("width");
  reader.skipSpace();
  const long long height = reader.dimension("height");
  reader.skipSpace();
  const double scale = reader.scale();
  reader.endOfHeader();

  const bool littleEndian = scale < 0.0;
  const bool swap = littleEndian != (std::endian::native == std::endian::little);
  const std::size_t rowValues = std::size_t(width) * channels;
  const std::size_t needed = rowValues * std::size_t(height) * 4;
  const std::size_t available = bytes.size() - reader.position();
  if (available < needed)
    invalidImageFile(path, "truncated PFM: " + std::to_string(available) + " data bytes, expected " +
                               std::to_string(needed));

  Image image(int(width), int(height), channels);
  const char* src = bytes.data() + reader.position();
  for (long long row = height - 1; row >= 0; --row) { // the file starts with the bottom row
    float* dst = image.pixels.data() + std::size_t(row) * rowValues;
    for (std::size_t i = 0; i < rowValues; ++i, src += 4) {
      std::uint32_t bits;
      std::memcpy(&bits, src, 4);
      if (swap) bits = byteSwap(bits);
      dst[i] = std::bit_cast<float>(bits);
    }
  }
  return image;
}

} // namespace rtlab::detail
