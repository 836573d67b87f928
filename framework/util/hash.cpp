#include "util/hash.h"

#include <cstring>

namespace rtlab {

namespace {
constexpr std::uint64_t kPrime = 0x100000001b3ull;
}

Fnv1a64& Fnv1a64::bytes(const void* data, std::size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  std::uint64_t h = m_state;
  for (std::size_t i = 0; i < size; ++i) {
    h ^= p[i];
    h *= kPrime;
  }
  m_state = h;
  return *this;
}

Fnv1a64& Fnv1a64::u64(std::uint64_t v) {
  unsigned char b[8];
  for (int i = 0; i < 8; ++i) b[i] = static_cast<unsigned char>(v >> (8 * i));
  return bytes(b, sizeof b);
}

Fnv1a64& Fnv1a64::text(const std::string& s) {
  u64(s.size());
  return bytes(s.data(), s.size());
}

Fnv1a64& Fnv1a64::f64(double v) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  return u64(bits);
}

Fnv1a64& Fnv1a64::f32(float v) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  return u64(bits);
}

std::string Fnv1a64::hex() const {
  static const char* kDigits = "0123456789abcdef";
  std::string s(16, '0');
  for (int i = 0; i < 16; ++i) s[15 - i] = kDigits[(m_state >> (4 * i)) & 15];
  return s;
}

std::uint64_t fnv1a64(const std::string& bytes) { return Fnv1a64().bytes(bytes.data(), bytes.size()).value(); }

} // namespace rtlab
