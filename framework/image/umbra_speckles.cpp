#include "image/umbra_speckles.h"

#include "util/error.h"

#include <cmath>
#include <vector>

namespace rtlab {
namespace {

bool surface(const Image& image, std::size_t i) { return !image.hasMask() || image.mask[i] > 0.5f; }

// 1 where every pixel within `r` (in x, or in y) of p is 1 in `in`; pixels outside the image
// count as 0, so the umbra never reaches the border.
std::vector<unsigned char> erode1d(const std::vector<unsigned char>& in, int w, int h, int r, bool alongX) {
  std::vector<unsigned char> out(in.size(), 0);
  const int lines = alongX ? h : w, length = alongX ? w : h;
  for (int line = 0; line < lines; ++line) {
    int run = 0; // length of the run of 1s ending at pos
    auto index = [&](int pos) { return alongX ? std::size_t(line) * w + pos : std::size_t(pos) * w + line; };
    std::vector<int> runs(length);
    for (int pos = 0; pos < length; ++pos) runs[pos] = run = in[index(pos)] ? run + 1 : 0;
    for (int pos = r; pos + r < length; ++pos)
      out[index(pos)] = runs[pos + r] >= 2 * r + 1 ? 1 : 0;
  }
  return out;
}

} // namespace

UmbraSpeckles measureUmbraSpeckles(const Image& reference, const Image& visibility, int erode, float threshold) {
  if (reference.channels != 1 || visibility.channels != 1 || reference.width != visibility.width ||
      reference.height != visibility.height)
    inputError("umbra speckles need two one-channel images of the same size");
  const int w = reference.width, h = reference.height;
  std::vector<unsigned char> umbra(reference.pixelCount());
  for (std::size_t i = 0; i < umbra.size(); ++i)
    umbra[i] = surface(reference, i) && surface(visibility, i) && reference.pixels[i] == 0.0f ? 1 : 0;
  if (erode > 0) umbra = erode1d(erode1d(umbra, w, h, erode, true), w, h, erode, false);
  UmbraSpeckles result;
  for (std::size_t i = 0; i < umbra.size(); ++i) {
    if (!umbra[i]) continue;
    ++result.umbraPixels;
    const float v = visibility.pixels[i];
    if (!std::isfinite(v) || v > threshold) ++result.speckles;
  }
  return result;
}

} // namespace rtlab
