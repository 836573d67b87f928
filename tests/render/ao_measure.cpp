#include "ao_measure.h"

#include "app/frame_options.h"
#include "app/reference_run.h"

#include <gtest/gtest.h>

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
  const ResolvedFrame resolved = resolvedOf(m.frame);
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

std::vector<std::string> joined(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

void expectGrazingFloorClear(const std::string& technique, const std::vector<std::string>& variants) {
  for (const std::string& extra : variants) {
    const auto m = measureAo("contact", technique, joined(kGrazingView, {extra}), 128, 0);
    EXPECT_EQ(m.glErrors, 0);
    const double fraction = fractionAtLeast(m.ao, 0.95f);
    std::printf("grazing floor, %s: %.4f of the floor at ao >= 0.95\n", extra.c_str(), fraction);
    EXPECT_GE(fraction, 0.98) << extra;
    EXPECT_TRUE(backgroundIsZero(m.ao)) << "sky pixels are excluded (0, mask 0)";
  }
}

std::vector<double> creaseProfile(const AoMeasurement& m) {
  std::vector<double> ao;
  for (float d : {0.05f, 0.2f, 0.35f, 0.6f, 0.75f}) {
    int x = 0, y = 0;
    if (!projectToPixel(m.frame, {1.2f, 0.0f, -2.75f + d}, x, y)) {
      ADD_FAILURE() << "crease point at " << d << " is off screen";
      ao.push_back(-1.0);
      continue;
    }
    ao.push_back(meanAround(m.ao, x, y, 1));
    std::printf("crease: floor at %.2f from the wall: ao %.3f (reference %.3f)\n", d, ao.back(),
                meanAround(m.reference, x, y, 1));
  }
  return ao;
}

void expectCreaseShape(const AoMeasurement& m, double beyondRadius) {
  const std::vector<double> ao = creaseProfile(m);
  EXPECT_LT(ao[0], 0.85) << "a point next to the wall is occluded";
  EXPECT_LT(ao[0], ao[1]);
  EXPECT_LT(ao[1], ao[2] + 0.02);
  EXPECT_GE(ao[3], beyondRadius) << "beyond ao.radius nothing occludes";
  EXPECT_GE(ao[4], beyondRadius);
}

void expectExtremesFinite(const std::string& technique, const std::vector<std::vector<std::string>>& cases) {
  for (const auto& sets : cases) {
    const auto m = measureAo("cornell", technique, sets, 64, 0);
    EXPECT_EQ(m.glErrors, 0);
    EXPECT_EQ(nonFiniteCount(m.ao), 0u) << sets.front();
    for (std::size_t i = 0; i < m.ao.pixelCount(); ++i) {
      ASSERT_GE(m.ao.pixels[i], 0.0f) << sets.front();
      ASSERT_LE(m.ao.pixels[i], 1.0f) << sets.front();
    }
    EXPECT_TRUE(backgroundIsZero(m.ao)) << sets.front();
  }
  // ao.radius near 0: nothing can occlude within it.
  const auto tiny = measureAo("cornell", technique, {"ao.radius=0.01"}, 64, 0);
  EXPECT_GE(fractionAtLeast(tiny.ao, 0.99f), 0.99);
}

void expectDebugViewsRender(const std::string& technique, const std::vector<std::string>& sets) {
  for (const char* half : {"false", "true"}) {
    const std::string halfSet = technique + ".half_resolution=" + half;
    TestFrame f = makeTestFrame("cornell", technique, joined({halfSet}, sets), 64, 48);
    const std::string raw = technique + ".raw", blurred = technique + ".blurred", pattern = technique + ".pattern";
    TestRender r = renderTestFrame(f, {raw, blurred, pattern, "ao"});
    EXPECT_EQ(r.glErrors, 0);
    const Image rawImage = r.renderer->readAov(raw);
    const Image blurredImage = r.renderer->readAov(blurred);
    const Image patternImage = r.renderer->readAov(pattern);
    const Image ao = r.renderer->readAov("ao");
    EXPECT_EQ(rawImage.width, 64);
    EXPECT_EQ(patternImage.channels, 3);
    for (std::size_t i = 0; i < ao.pixelCount(); ++i)
      ASSERT_NEAR(blurredImage.pixels[i], ao.pixels[i], 1e-3) << "the blurred view is the stage output";
    // The pattern view marks the centre pixel's taps: some pixel is pure green or red.
    int marks = 0;
    for (std::size_t i = 0; i < patternImage.pixelCount(); ++i)
      if (patternImage.pixels[i * 3 + 2] == 0.0f &&
          std::abs(patternImage.pixels[i * 3] + patternImage.pixels[i * 3 + 1] - 1.0f) < 1e-4f)
        ++marks;
    EXPECT_GT(marks, 0) << halfSet;
  }
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
