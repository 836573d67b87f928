// What the arealight techniques' tests share (test_area_mc.cpp, test_ltc_reference.cpp): the AOV
// `arealight` of a test frame, the `arealight` reference of the same frame, and their error over
// the reference's surface pixels.
#pragma once
#include "app/reference_run.h"
#include "render_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace rtlab::test {

// The frame with the material named "floor" at `roughness` (a new scene name: the fixture shares
// renderers per name).
inline TestFrame withFloorRoughness(TestFrame f, float roughness, const std::string& name) {
  bool found = false;
  for (Material& m : f.scene.materials)
    if (m.name == "floor") {
      m.roughness = roughness;
      found = true;
    }
  EXPECT_TRUE(found);
  f.scene.name = name;
  return f;
}

inline Image arealightAov(const TestFrame& f) {
  const TestRender r = renderTestFrame(f, {"arealight"});
  EXPECT_EQ(r.glErrors, 0);
  return r.renderer->readAov("arealight");
}

inline Image arealightReference(const TestFrame& f, int spp) {
  TestRender r = renderTestFrame(f, {"arealight"});
  return renderReferenceFrame(*r.renderer, resolvedOf(f), "arealight", spp, false);
}

struct ArealightError {
  double rmse = 0.0, mean = 0.0, bias = 0.0; // over the reference's surface pixels, every channel
  double relative() const { return rmse / mean; }
};

inline ArealightError arealightError(const Image& got, const Image& ref) {
  EXPECT_EQ(got.width, ref.width);
  EXPECT_EQ(got.channels, 3);
  ArealightError e;
  double n = 0.0, sum2 = 0.0, diff = 0.0, sum = 0.0;
  for (std::size_t i = 0; i < ref.pixelCount(); ++i) {
    if (ref.mask[i] < 0.5f) continue;
    for (int c = 0; c < 3; ++c) {
      const double a = got.pixels[i * 3 + c], b = ref.pixels[i * 3 + c];
      sum2 += (a - b) * (a - b);
      diff += a - b;
      sum += b;
      n += 1.0;
    }
  }
  e.rmse = std::sqrt(sum2 / n);
  e.mean = sum / n;
  e.bias = diff / n;
  return e;
}

// The relative RMSE (rmse / mean radiance of the reference) of `got` against `ref` per roughness
// of arealight_ramp's strips: bin b holds the surface pixels whose G-buffer roughness (as the
// reference reads it) rounds to b / 10; `values` counts the channel values of each bin.
struct RoughnessBin {
  double values = 0.0, relative = 0.0;
};
inline std::vector<RoughnessBin> errorPerRoughness(const TestFrame& f, const Image& got, const Image& ref) {
  TestRender r = renderTestFrame(f, {"arealight"});
  const ReferenceInput input = referenceInput(*r.renderer, resolvedOf(f));
  constexpr int kBins = 11;
  std::vector<double> err2(kBins, 0.0), sum(kBins, 0.0);
  std::vector<RoughnessBin> bins(kBins);
  for (std::size_t i = 0; i < ref.pixelCount(); ++i) {
    if (ref.mask[i] < 0.5f) continue;
    const int bin = std::clamp(int(std::lround(input.surfaces.roughness[i] * 10.0f)), 0, kBins - 1);
    for (int c = 0; c < 3; ++c) {
      const double d = double(got.pixels[i * 3 + c]) - ref.pixels[i * 3 + c];
      err2[bin] += d * d;
      sum[bin] += ref.pixels[i * 3 + c];
      bins[bin].values += 1.0;
    }
  }
  for (int b = 0; b < kBins; ++b)
    if (bins[b].values > 0.0) bins[b].relative = std::sqrt(err2[b] / bins[b].values) / (sum[b] / bins[b].values);
  return bins;
}

} // namespace rtlab::test
