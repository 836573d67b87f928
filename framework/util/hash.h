// FNV-1a, 64 bit: a small, dependency-free content hash for cache keys (the sweep's reference
// cache). Not cryptographic: it identifies content, it does not authenticate it.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

namespace rtlab {

class Fnv1a64 {
public:
  Fnv1a64& bytes(const void* data, std::size_t size);
  // Length-prefixed, so ("ab", "c") and ("a", "bc") hash differently.
  Fnv1a64& text(const std::string& s);
  Fnv1a64& u64(std::uint64_t v);  // little-endian bytes, whatever the host
  Fnv1a64& f64(double v);         // the IEEE bit pattern; -0 and 0 differ, as they may render differently
  Fnv1a64& f32(float v);

  std::uint64_t value() const { return m_state; }
  std::string hex() const; // 16 lowercase hex digits

private:
  std::uint64_t m_state = 0xcbf29ce484222325ull;
};

// Hash of a byte string in one call.
std::uint64_t fnv1a64(const std::string& bytes);

} // namespace rtlab
