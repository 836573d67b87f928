#include "ao_measure.h"

#include "app/frame_options.h"
#include "app/reference_run.h"

#include <cmath>
#include <cstdio>

namespace rtlab::test {

AoMeasurement measureAo(const std::string& scene, const std::string& technique, const std::vector<std::string>& sets,
                        int size, int spp) {
  AoMeasurement m;
  m.frame = makeTestFrame(scene, technique, sets, size, size);
  TestRender r = renderTestFrame(m.frame, {"ao"});
  m.glErrors = r.glErrors;
  m.ao = r.renderer->readAov("ao");
  if (spp <= 0) return m;
  ResolvedFrame resolved;
  resolved.options.width = size;
  resolved.options.height = size;
  resolved.scene = m.frame.scene;
  resolved.params = m.frame.params;
  resolved.techniques = m.frame.techniques;
  m.reference = renderReferenceFrame(*r.renderer, resolved, "ao", spp, false);
  m.metrics = computeMetrics(m.reference, m.ao);
  Image one = m.ao;
  for (std::size_t i = 0; i < one.pixelCount(); ++i)
    one.pixels[i] = one.mask[i] >= 0.5f ? 1.0f : 0.0f;
  m.noAo = computeMetrics(m.reference, one);
  std::string label;
  for (const auto& s : sets)
    label += s + " ";
  std::printf("ao %-6s %-8s %-60s rmse %.4f (no AO %.4f)\n", technique.c_str(), scene.c_str(), label.c_str(),
              m.metrics.rmse, m.noAo.rmse);
  return m;
}

double meanAround(const Image& image, int x, int y, int r) {
  double sum = 0.0;
  int n = 0;
  for (int j = y - r; j <= y + r; ++j)
    for (int i = x - r; i <= x + r; ++i) {
      if (i < 0 || j < 0 || i >= image.width || j >= image.height) continue;
      if (image.mask[std::size_t(j) * image.width + i] < 0.5f) continue;
      sum += image.at(i, j, 0);
      ++n;
    }
  return n ? sum / n : -1.0;
}

double fractionAtLeast(const Image& image, float threshold) {
  std::size_t n = 0, above = 0;
  for (std::size_t i = 0; i < image.pixelCount(); ++i) {
    if (image.mask[i] < 0.5f) continue;
    ++n;
    if (image.pixels[i * image.channels] >= threshold) ++above;
  }
  return n ? double(above) / double(n) : 0.0;
}

std::size_t nonFiniteCount(const Image& image) {
  std::size_t n = 0;
  for (float v : image.pixels)
    if (!std::isfinite(v)) ++n;
  return n;
}

bool backgroundIsZero(const Image& image) {
  for (std::size_t i = 0; i < image.pixelCount(); ++i)
    if (image.mask[i] < 0.5f)
      for (int c = 0; c < image.channels; ++c)
        if (image.pixels[i * image.channels + c] != 0.0f) return false;
  return true;
}

} // namespace rtlab::test
