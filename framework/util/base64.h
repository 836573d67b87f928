// Base64 (RFC 4648, standard alphabet, padded): images embedded in self-contained HTML reports as
// data: URIs.
#pragma once
#include <cstddef>
#include <string>

namespace rtlab {

std::string base64Encode(const void* data, std::size_t size);
inline std::string base64Encode(const std::string& bytes) { return base64Encode(bytes.data(), bytes.size()); }

} // namespace rtlab
