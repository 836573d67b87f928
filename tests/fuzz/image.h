// The three image fuzz targets (pfm.cpp, exr.cpp, png.cpp): a decoder of framework/image on the
// input bytes (the decoders work in memory; image_io.cpp only reads the file), then the
// invariants every decoded image must hold (image_io_internal.h validateImage).
#pragma once
#include "image/image_io_internal.h"

#include "fuzz_target.h"

namespace rtlab::fuzz {

template <typename Decode>
int decodeImage(const std::uint8_t* data, std::size_t size, Decode decode) {
  if (size > kMaxInputBytes) return -1;
  expectOnlyErrors([&] {
    const Image image = decode(std::string(text(data, size)), "fuzz-input");
    detail::validateImage(image, "fuzz-input"); // Error(Internal) would be a decoder bug
  });
  return 0;
}

} // namespace rtlab::fuzz
