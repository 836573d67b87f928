// Error heat maps for reports (metrics.h errorHeatmap): the magma colormap of S. van der Walt and
// N. Smith (matplotlib, 2015; released CC0), perceptually uniform and readable in grayscale, the
// colormap FLIP's paper (Andersson et al. 2020) uses for its error maps. The 17 control points
// below are entries 0, 16, 32, ..., 240 and 255 of its 256-entry table; between them the colour is
// interpolated linearly, which stays within a few 1/255 steps of the full table.
#include "image/metrics.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rtlab {
namespace {

constexpr std::array<std::array<float, 3>, 17> kMagma = {{
    {0.001462f, 0.000466f, 0.013866f}, // 0
    {0.039608f, 0.031090f, 0.133515f}, // 16
    {0.113094f, 0.065492f, 0.276784f}, // 32
    {0.211718f, 0.061992f, 0.418647f}, // 48
    {0.316654f, 0.071690f, 0.485380f}, // 64
    {0.414709f, 0.110431f, 0.504662f}, // 80
    {0.512831f, 0.148179f, 0.507648f}, // 96
    {0.613617f, 0.181811f, 0.498536f}, // 112
    {0.716387f, 0.214982f, 0.475290f}, // 128
    {0.816914f, 0.255895f, 0.436461f}, // 144
    {0.904281f, 0.319610f, 0.388137f}, // 160
    {0.960949f, 0.418323f, 0.359630f}, // 176
    {0.986700f, 0.535582f, 0.382210f}, // 192
    {0.996096f, 0.653659f, 0.446213f}, // 208
    {0.996898f, 0.769591f, 0.534892f}, // 224
    {0.992440f, 0.884330f, 0.640099f}, // 240
    {0.987053f, 0.991438f, 0.749504f}, // 255
}};

// Table position (0..255) of control point k.
float controlIndex(int k) { return float(std::min(16 * k, 255)); }

std::array<float, 3> magma(float t) {
  const float index = std::clamp(t, 0.0f, 1.0f) * 255.0f;
  int k = std::min(int(index / 16.0f), int(kMagma.size()) - 2);
  while (k > 0 && index < controlIndex(k)) --k;
  const float f = (index - controlIndex(k)) / (controlIndex(k + 1) - controlIndex(k));
  std::array<float, 3> c;
  for (int i = 0; i < 3; ++i) c[i] = kMagma[k][i] + f * (kMagma[k + 1][i] - kMagma[k][i]);
  return c;
}

} // namespace

Image errorHeatmap(const Image& error, float maxError) {
  Image out(error.width, error.height, 3);
  const std::size_t n = error.pixelCount();
  for (std::size_t i = 0; i < n; ++i) {
    std::array<float, 3> c;
    const float e = error.channels > 0 ? error.pixels[i * error.channels] : 0.0f;
    if (error.hasMask() && !(error.mask[i] > 0.5f)) {
      c = {0.5f, 0.5f, 0.5f};
    } else if (!std::isfinite(e)) {
      c = magma(1.0f); // a non-finite error is as large as it gets
    } else {
      const float t = maxError > 0.0f && std::isfinite(maxError) ? e / maxError : (e > 0.0f ? 1.0f : 0.0f);
      c = magma(t);
    }
    for (int k = 0; k < 3; ++k) out.pixels[i * 3 + k] = c[k];
  }
  return out;
}

} // namespace rtlab
