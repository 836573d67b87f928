// The grade cache's entries (exercise/grade_cache.h, docs/exercises.md "The grade cache"): an
// image read back is bit-identical to the one stored (NaN, infinities, -0 and the mask included);
// an entry of another key, another size or count, a truncated one and one with an altered byte
// are misses (with a warning), never wrong images; a folder that cannot be made is exit 6.
#include "exercise/grade_cache.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>

namespace fs = std::filesystem;
using rtlab::GradeCache;
using rtlab::Image;

namespace {

Image pattern(int w, int h, int c, bool mask, float seed) {
  Image image(w, h, c);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = std::sin(seed + float(i)) * 3.0f;
  image.pixels[0] = std::numeric_limits<float>::quiet_NaN();
  image.pixels[1] = -0.0f;
  image.pixels[2] = std::numeric_limits<float>::infinity();
  if (mask) {
    image.mask.resize(image.pixelCount());
    for (std::size_t i = 0; i < image.mask.size(); ++i) image.mask[i] = float(i % 2);
  }
  return image;
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

} // namespace

TEST(GradeCache, EntriesReadBackBitIdentical) {
  const GradeCache cache((rtlab::test::freshTestDir("grade_cache") / "cache").string());
  const Image a = pattern(7, 5, 3, true, 1.0f), b = pattern(7, 5, 1, false, 2.0f);
  EXPECT_FALSE(cache.load("k1", 2, 7, 5)) << "nothing stored yet";
  cache.store("k1", {a, b});
  const auto back = cache.load("k1", 2, 7, 5);
  ASSERT_TRUE(back);
  ASSERT_EQ(back->size(), 2u);
  EXPECT_EQ((*back)[0].channels, 3);
  EXPECT_TRUE(sameBits((*back)[0].pixels, a.pixels));
  EXPECT_TRUE(sameBits((*back)[0].mask, a.mask));
  EXPECT_EQ((*back)[1].channels, 1);
  EXPECT_TRUE(sameBits((*back)[1].pixels, b.pixels));
  EXPECT_FALSE((*back)[1].hasMask());
}

TEST(GradeCache, ABadEntryIsAMissNeverWrongImages) {
  const GradeCache cache((rtlab::test::freshTestDir("grade_cache") / "cache").string());
  cache.store("k1", {pattern(4, 4, 3, false, 1.0f)});
  EXPECT_FALSE(cache.load("k1", 2, 4, 4)) << "another count";
  EXPECT_FALSE(cache.load("k1", 1, 4, 5)) << "another size";
  fs::copy_file(cache.entryPath("k1"), cache.entryPath("k2"));
  EXPECT_FALSE(cache.load("k2", 1, 4, 4)) << "an entry renamed to another key";
  const std::string bytes = rtlab::test::slurp(cache.entryPath("k1"));
  for (std::size_t cut : {std::size_t(0), std::size_t(10), bytes.size() - 1}) {
    rtlab::test::writeText(cache.entryPath("k1"), bytes.substr(0, cut));
    EXPECT_FALSE(cache.load("k1", 1, 4, 4)) << "truncated to " << cut;
  }
  for (std::size_t at : {std::size_t(3), bytes.find('\n') + 1, bytes.size() - 1}) {
    std::string altered = bytes;
    altered[at] = char(altered[at] ^ 1);
    rtlab::test::writeText(cache.entryPath("k1"), altered);
    EXPECT_FALSE(cache.load("k1", 1, 4, 4)) << "byte " << at << " altered";
  }
  rtlab::test::writeText(cache.entryPath("k1"), bytes + "x");
  EXPECT_FALSE(cache.load("k1", 1, 4, 4)) << "padded";
  rtlab::test::writeText(cache.entryPath("k1"), bytes);
  EXPECT_TRUE(cache.load("k1", 1, 4, 4)) << "the sound entry";
}

TEST(GradeCache, AFolderThatCannotBeMadeIsAnOutputError) {
  const fs::path dir = rtlab::test::freshTestDir("grade_cache");
  rtlab::test::writeText(dir / "file", "x");
  for (const fs::path& bad : {dir / "file", dir / "file" / "sub"}) {
    const auto caught = rtlab::test::catchError([&] { GradeCache cache(bad.string()); });
    rtlab::test::checkCaught(caught, rtlab::ExitCode::Output, {"--cache " + bad.string()});
  }
}
