#include "util/base64.h"

namespace rtlab {

std::string base64Encode(const void* data, std::size_t size) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* p = static_cast<const unsigned char*>(data);
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < size; i += 3) {
    const unsigned v = unsigned(p[i]) << 16 | unsigned(p[i + 1]) << 8 | p[i + 2];
    out += k[v >> 18];
    out += k[(v >> 12) & 63];
    out += k[(v >> 6) & 63];
    out += k[v & 63];
  }
  if (i < size) {
    const unsigned v = unsigned(p[i]) << 16 | (i + 1 < size ? unsigned(p[i + 1]) << 8 : 0u);
    out += k[v >> 18];
    out += k[(v >> 12) & 63];
    out += i + 1 < size ? k[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

} // namespace rtlab
