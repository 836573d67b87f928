// Fuzz target: the PFM decoder (framework/image/pfm_io.cpp) on the input bytes.
#include "image.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return rtlab::fuzz::decodeImage(data, size, rtlab::detail::decodePfm);
}
