// Images as raw bytes with a small JSON shape: how the grader's workers stream their renders
// (docs/exercises.md "Safety") and how the grade cache stores them (docs/exercises.md "The grade
// cache"). The bytes are the floats of the pixels in memory order, then the mask's when there is
// one, so an image read back is bit-identical to the one written (NaN payloads, -0 and all).
#pragma once
#include "image/image.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>

namespace rtlab {

// [width, height, channels, has_mask]
nlohmann::json rawImageShape(const Image& image);
// The byte count of an image of that shape. Throws std::invalid_argument for a shape that is not
// [w, h, c, bool] with 1 <= w, h <= 65536 and 1 <= c <= 4 (a corrupt file never allocates wildly).
std::size_t rawImageBytes(const nlohmann::json& shape);
void appendRawImage(std::string& out, const Image& image);
// The image of `shape` from rawImageBytes(shape) bytes at `bytes`.
Image rawImageFrom(const nlohmann::json& shape, const char* bytes);

} // namespace rtlab
