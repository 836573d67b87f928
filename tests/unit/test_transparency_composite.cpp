// compositeOver (framework/reference/transparency_reference.h): the exact Over of captured
// fragments, sorted per pixel, whatever order they were captured in.
#include "reference/transparency_reference.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace rtlab {
namespace {

CapturedFragment frag(std::uint32_t x, std::uint32_t y, float depth, float c, float alpha) {
  CapturedFragment f;
  f.x = x;
  f.y = y;
  f.depth = depth;
  f.r = f.g = f.b = c;
  f.alpha = alpha;
  return f;
}

Image opaqueOf(int w, int h, float value) {
  Image img(w, h, 3);
  std::fill(img.pixels.begin(), img.pixels.end(), value);
  return img;
}

TEST(TransparencyComposite, SortsEachPixelAndCompositesBackToFront) {
  CapturedFragments c;
  c.width = 2;
  c.height = 1;
  // Pixel (0, 0): near (depth 0.2, C 1, a 0.5) over far (depth 0.6, C 0.25, a 0.5) over opaque 0.
  // Captured far first at one pixel and near first at the other: the same result.
  c.fragments = {frag(0, 0, 0.6f, 0.25f, 0.5f), frag(0, 0, 0.2f, 1.0f, 0.5f), frag(1, 0, 0.2f, 1.0f, 0.5f),
                 frag(1, 0, 0.6f, 0.25f, 0.5f)};
  const Image out = compositeOver(c, opaqueOf(2, 1, 0.0f));
  // 0.5*1 + 0.5*(0.5*0.25 + 0.5*0) = 0.5625
  EXPECT_DOUBLE_EQ(out.at(0, 0, 0), 0.5625);
  EXPECT_DOUBLE_EQ(out.at(1, 0, 2), 0.5625);
  std::reverse(c.fragments.begin(), c.fragments.end());
  EXPECT_EQ(compositeOver(c, opaqueOf(2, 1, 0.0f)).pixels, out.pixels);
}

TEST(TransparencyComposite, NoFragmentsOrZeroAlphaLeavesTheOpaqueColourExactly) {
  CapturedFragments c;
  c.width = 3;
  c.height = 2;
  c.fragments = {frag(1, 1, 0.5f, 7.0f, 0.0f)};
  Image opaque = opaqueOf(3, 2, 0.3f);
  opaque.mask.assign(6, 0.0f);
  opaque.mask[0] = 1.0f;
  const Image out = compositeOver(c, opaque);
  EXPECT_EQ(out.pixels, opaque.pixels);
  // Covered: the opaque surface at (0, 0), the fragment at (1, 1); nothing else.
  EXPECT_EQ(out.mask, (std::vector<float>{1, 0, 0, 0, 1, 0}));
}

TEST(TransparencyComposite, EqualDepthsHaveOneOrderWhateverTheCaptureOrder) {
  CapturedFragments c;
  c.width = c.height = 1;
  c.fragments = {frag(0, 0, 0.5f, 1.0f, 0.5f), frag(0, 0, 0.5f, 0.0f, 0.9f)};
  const Image a = compositeOver(c, opaqueOf(1, 1, 0.2f));
  std::swap(c.fragments[0], c.fragments[1]);
  EXPECT_EQ(compositeOver(c, opaqueOf(1, 1, 0.2f)).pixels, a.pixels);
}

TEST(TransparencyComposite, RejectsFragmentsOutsideTheFrameAndMismatchedSizes) {
  CapturedFragments c;
  c.width = 2;
  c.height = 2;
  c.fragments = {frag(2, 0, 0.5f, 1.0f, 0.5f)};
  EXPECT_THROW(compositeOver(c, opaqueOf(2, 2, 0.0f)), Error);
  c.fragments.clear();
  EXPECT_THROW(compositeOver(c, opaqueOf(3, 2, 0.0f)), Error);
}

TEST(TransparencyComposite, StopsWhenCancelled) {
  CapturedFragments c;
  c.width = c.height = 4;
  std::atomic<bool> cancel{true};
  try {
    compositeOver(c, opaqueOf(4, 4, 0.0f), &cancel);
    FAIL() << "not cancelled";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::Interrupted);
  }
}

} // namespace
} // namespace rtlab
