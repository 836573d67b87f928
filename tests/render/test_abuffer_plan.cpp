// The A-buffer's memory plan (techniques/common/transparency/abuffer_plan.h): bands and split parts tile their
// rectangle exactly (every pixel once), band counts follow the expected nodes, and the pool never
// exceeds the budget, the GL limit or the end-of-list marker.
#include "techniques/common/transparency/abuffer_plan.h"

#include <gtest/gtest.h>

#include <vector>

namespace rtlab::abuffer {
namespace {

// Every pixel of `outer` is in exactly one of `parts`, none outside it.
void expectTiles(const Rect& outer, const std::vector<Rect>& parts) {
  std::vector<int> hits(outer.pixels(), 0);
  for (const Rect& r : parts) {
    ASSERT_GT(r.width, 0);
    ASSERT_GT(r.height, 0);
    for (int y = r.y; y < r.y + r.height; ++y)
      for (int x = r.x; x < r.x + r.width; ++x) {
        ASSERT_TRUE(x >= outer.x && x < outer.x + outer.width && y >= outer.y && y < outer.y + outer.height);
        ++hits[std::size_t(y - outer.y) * std::size_t(outer.width) + std::size_t(x - outer.x)];
      }
  }
  for (int h : hits) ASSERT_EQ(h, 1);
}

TEST(AbufferPlan, BandsTileTheFrame) {
  for (int count : {1, 2, 3, 7, 90, 500})
    expectTiles({0, 0, 160, 90}, bands(160, 90, count));
  EXPECT_EQ(bands(160, 90, 500).size(), 90u); // at most one row a band
}

TEST(AbufferPlan, SplitPartsTileTheRectangleAlongItsLongerSide) {
  const Rect tall{3, 5, 20, 40}, wide{0, 7, 64, 3};
  const std::vector<Rect> a = split(tall, 1000, 300), b = split(wide, 1000, 300);
  expectTiles(tall, a);
  expectTiles(wide, b);
  EXPECT_EQ(a.size(), 5u); // ceil(1.25 * 1000 / 300)
  for (const Rect& r : a) EXPECT_EQ(r.width, 20);
  for (const Rect& r : b) EXPECT_EQ(r.height, 3);
  const std::vector<Rect> pixel = split({4, 4, 1, 1}, 1000, 300); // a pixel is not split
  ASSERT_EQ(pixel.size(), 1u);
  EXPECT_EQ(pixel[0], (Rect{4, 4, 1, 1}));
  expectTiles({0, 0, 2, 1}, split({0, 0, 2, 1}, 1000000, 1));                       // at most one pixel wide
}

TEST(AbufferPlan, BandCountAndPoolStayWithinTheLimits) {
  const std::uint64_t gl = std::uint64_t(128) << 20; // llvmpipe's GL_MAX_SHADER_STORAGE_BLOCK_SIZE
  EXPECT_EQ(maxNodes(std::uint64_t(1) << 30, gl), 8388608u);
  EXPECT_EQ(maxNodes(64 * 1024, gl), 4096u);
  EXPECT_EQ(maxNodes(0, gl), 1u);
  EXPECT_LT(maxNodes(std::uint64_t(1) << 40, std::uint64_t(1) << 40), kEndOfList);
  EXPECT_EQ(bandCount(0, 8388608, 720), 1);
  EXPECT_EQ(bandCount(6373875, 8388608, 720), 1);       // layers at 1280x720
  EXPECT_EQ(bandCount(1280ull * 720 * 24, 8388608, 720), 3); // 24 layers everywhere
  EXPECT_EQ(bandCount(std::uint64_t(1) << 40, 1, 720), 720);
  EXPECT_EQ(grownCapacity(100, 1000), 125u);
  EXPECT_EQ(grownCapacity(900, 1000), 1000u);
  EXPECT_EQ(grownCapacity(0, 1000), 1u);
}

} // namespace
} // namespace rtlab::abuffer
