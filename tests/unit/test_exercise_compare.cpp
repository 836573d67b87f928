// Judging a student's view against the solution (docs/exercises.md "Grading"): the tolerances and
// the recognised causes.
#include "exercise/view_compare.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace rtlab;

namespace {

// A 20x10 visibility image: a shadowed left half (0.2), lit right half (1.0), a background column
// (mask 0) at x = 0.
Image solutionImage() {
  Image img(20, 10, 1);
  img.mask.assign(img.pixelCount(), 1.0f);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 20; ++x) {
      img.at(x, y, 0) = x < 10 ? 0.2f : 1.0f;
      if (x == 0) {
        img.mask[std::size_t(y) * 20] = 0.0f;
        img.at(x, y, 0) = 0.0f;
      }
    }
  return img;
}

Image constant(float v) {
  Image img = solutionImage();
  for (auto& p : img.pixels) p = v;
  return img;
}

const ExerciseTolerance kTol{0.02, 0.01, 0.01};

} // namespace

TEST(ExerciseCompare, IdenticalAndWithinTolerancePass) {
  const Image sol = solutionImage();
  EXPECT_TRUE(compareWithSolution(sol, sol, nullptr, kTol).passed);
  Image near = sol;
  for (auto& p : near.pixels) p += 0.008f; // under the per-pixel and the RMSE tolerance
  const auto c = compareWithSolution(near, sol, nullptr, kTol);
  EXPECT_TRUE(c.passed) << c.cause;
  EXPECT_DOUBLE_EQ(c.differingFraction, 0.0);
  // One flipped pixel of 190 valid ones (0.53%) is within a 1% fraction, however far it is off
  // (RMSE sqrt(0.64/190) = 0.058): the fraction bounds outliers, not the RMSE.
  Image one = sol;
  one.at(5, 5, 0) = 1.0f;
  const auto flipped = compareWithSolution(one, sol, nullptr, kTol);
  EXPECT_TRUE(flipped.passed) << flipped.cause;
  EXPECT_NEAR(flipped.rmseVsSolution, std::sqrt(0.64 / 190.0), 1e-6);
  EXPECT_DOUBLE_EQ(flipped.rmseAgreeing, 0.0);
  // Two flipped pixels exceed the fraction.
  one.at(6, 5, 0) = 1.0f;
  EXPECT_FALSE(compareWithSolution(one, sol, nullptr, kTol).passed);
  // A small error everywhere, under the per-pixel tolerance but over the RMSE bound, fails.
  Image biased = sol;
  for (auto& p : biased.pixels) p -= 0.015f;
  const auto b = compareWithSolution(biased, sol, nullptr, kTol);
  EXPECT_FALSE(b.passed);
  EXPECT_DOUBLE_EQ(b.differingFraction, 0.0);
  EXPECT_NE(b.cause.find("a small error everywhere"), std::string::npos) << b.cause;
}

TEST(ExerciseCompare, BackgroundPixelsAreIgnored) {
  const Image sol = solutionImage();
  Image s = sol;
  for (int y = 0; y < 10; ++y) s.at(0, y, 0) = 7.0f; // the masked-out column
  EXPECT_TRUE(compareWithSolution(s, sol, nullptr, kTol).passed);
}

TEST(ExerciseCompare, RecognisesTheStub) {
  const Image sol = solutionImage(), stub = constant(1.0f);
  const auto c = compareWithSolution(stub, sol, &stub, kTol);
  EXPECT_FALSE(c.passed);
  EXPECT_EQ(c.cause.rfind("stub:", 0), 0u) << c.cause;
}

TEST(ExerciseCompare, RecognisesAnInvertedResult) {
  const Image sol = solutionImage();
  Image inv = sol;
  for (auto& p : inv.pixels) p = 1.0f - p;
  const auto c = compareWithSolution(inv, sol, nullptr, kTol);
  EXPECT_FALSE(c.passed);
  EXPECT_EQ(c.cause.rfind("inverted:", 0), 0u) << c.cause;
}

TEST(ExerciseCompare, RecognisesNonFinitePixels) {
  const Image sol = solutionImage();
  Image s = sol;
  s.at(3, 3, 0) = std::numeric_limits<float>::quiet_NaN();
  s.at(4, 3, 0) = std::numeric_limits<float>::infinity();
  const auto c = compareWithSolution(s, sol, nullptr, kTol);
  EXPECT_FALSE(c.passed); // even one NaN fails the view
  EXPECT_EQ(c.nonFinite, 2u);
  EXPECT_EQ(c.cause.rfind("nan: 2 pixels", 0), 0u) << c.cause;
}

TEST(ExerciseCompare, RecognisesOutOfRangeAndConstantValues) {
  const Image sol = solutionImage();
  Image big = sol;
  for (auto& p : big.pixels) p *= 16.0f; // a sum not divided by its count
  auto c = compareWithSolution(big, sol, nullptr, kTol);
  EXPECT_EQ(c.cause.rfind("range:", 0), 0u) << c.cause;
  c = compareWithSolution(constant(0.5f), sol, nullptr, kTol);
  EXPECT_EQ(c.cause.rfind("constant: every pixel is 0.5", 0), 0u) << c.cause;
}

TEST(ExerciseCompare, OtherwiseSaysHowMuchAndWhichWay) {
  const Image sol = solutionImage();
  Image dark = sol;
  for (int y = 0; y < 10; ++y)
    for (int x = 10; x < 14; ++x) dark.at(x, y, 0) = 0.2f; // shadow too wide: darker
  const auto c = compareWithSolution(dark, sol, nullptr, kTol);
  EXPECT_FALSE(c.passed);
  EXPECT_EQ(c.cause.rfind("differs: 21% of the pixels", 0), 0u) << c.cause;
  EXPECT_NE(c.cause.find("mostly darker"), std::string::npos) << c.cause;
  EXPECT_LT(c.meanSignedDifference, 0.0);
}

TEST(ExerciseCompare, DifferentSizesAreInputErrors) {
  Image small(4, 4, 1);
  rtlab::test::checkCaught(rtlab::test::catchError([&] { compareWithSolution(small, solutionImage(), nullptr, kTol); }),
                           ExitCode::Input, {"differ in size"});
}
