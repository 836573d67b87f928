// The progressive reference (framework/reference/progressive_reference.h) on the synthetic
// scenes of the reference tests: it converges to the closed form and to renderReference, a
// restart is prompt and bumps the generation, latest() copies only what is new, bad input throws
// at once, and a seed gives the same images whatever the thread count.
#include "reference/progressive_reference.h"
#include "util/error.h"

#include "test_reference_scenes.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

namespace rtlab {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

ProgressiveOptions progressive(int targetSpp, float aoRadius, unsigned seed = 1, int threads = 2) {
  ProgressiveOptions o;
  o.targetSpp = targetSpp;
  o.aoRadius = aoRadius;
  o.seed = seed;
  o.threads = threads;
  return o;
}

// Polls until the job converges (or 120 s pass: a failure, not a hang) and returns its mean.
ProgressiveSnapshot waitConverged(const ProgressiveReference& ref) {
  ProgressiveSnapshot snap;
  const auto start = Clock::now();
  while (!(snap.converged && snap.generation == ref.generation()) && secondsSince(start) < 120.0) {
    if (!ref.latest(snap)) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    EXPECT_EQ(ref.error(), "");
  }
  EXPECT_TRUE(snap.converged) << "no convergence within 120 s";
  return snap;
}

double rmse(const Image& im, const std::vector<double>& expected) {
  double sum = 0.0;
  for (std::size_t i = 0; i < expected.size(); ++i)
    sum += std::pow(im.pixels[i] - expected[i], 2.0);
  return std::sqrt(sum / double(expected.size()));
}

TEST(ProgressiveReference, BatchesDoubleUpToTheCapAndStopAtTheTarget) {
  ProgressiveOptions o;
  o.targetSpp = 40;
  o.batchMaxSpp = 8;
  std::vector<int> batches;
  for (int k = 0, done = 0; done < o.targetSpp; ++k) {
    batches.push_back(progressiveBatchSpp(k, done, o));
    done += batches.back();
  }
  EXPECT_EQ(batches, (std::vector<int>{1, 1, 2, 4, 8, 8, 8, 8}));
  EXPECT_NE(progressiveBatchSeed(1, 0), progressiveBatchSeed(1, 1));
  EXPECT_NE(progressiveBatchSeed(1, 0), progressiveBatchSeed(2, 0));
}

TEST(ProgressiveReference, ConvergesToTheClosedFormAndToTheSinglePassReference) {
  const test::WallCase c = test::wallCase(32, 16, 0.95f); // every pixel within R of the wall
  double variance = 0.0; // mean over pixels of p (1 - p): one independent binary sample's variance
  for (double p : c.expected)
    variance += p * (1.0 - p) / double(c.expected.size());
  std::vector<double> errors;
  for (int spp : {4, 16, 64, 256}) {
    ProgressiveReference ref;
    ref.start(c.scene, c.points, "ao", progressive(spp, c.radius));
    const ProgressiveSnapshot snap = waitConverged(ref);
    ASSERT_EQ(snap.samples, spp);
    ASSERT_EQ(snap.image.channels, 1);
    errors.push_back(rmse(snap.image, c.expected));
    // Every batch is at least as good as independent samples, so the mean of spp samples has a
    // variance of at most p (1 - p) / spp per pixel; over 512 pixels the RMSE is measured to a few
    // percent, hence the margin of 1.25 (plus the closed form's 1e-3, as in test_reference.cpp).
    EXPECT_LE(errors.back(), 1.25 * std::sqrt(variance / spp) + 1e-3) << spp << " spp";
    if (spp == 256) {
      ReferenceOptions single;
      single.spp = 256;
      single.aoRadius = c.radius;
      const Image once = renderReference(c.scene, c.points, "ao", single);
      EXPECT_EQ(once.mask, snap.image.mask);
      // Two independent estimates of the same mean, each within sqrt(variance / 256).
      EXPECT_LE(rmse(snap.image, std::vector<double>(once.pixels.begin(), once.pixels.end())),
                1.25 * std::sqrt(2.0 * variance / 256));
    }
  }
  for (std::size_t i = 1; i < errors.size(); ++i)
    EXPECT_LT(errors[i], errors[i - 1]) << "step " << i;
}

TEST(ProgressiveReference, LatestCopiesOnlyWhatIsNew) {
  const test::WallCase c = test::wallCase(8, 4, 0.95f);
  ProgressiveReference ref;
  ProgressiveSnapshot snap;
  EXPECT_FALSE(ref.latest(snap)); // nothing started
  EXPECT_EQ(ref.generation(), 0u);
  EXPECT_EQ(ref.start(c.scene, c.points, "ao", progressive(8, c.radius)), 1u);
  snap = waitConverged(ref);
  EXPECT_EQ(snap.generation, 1u);
  EXPECT_EQ(snap.samples, 8);
  EXPECT_FALSE(ref.running());
  ProgressiveSnapshot again = snap;
  again.image.pixels.assign(again.image.pixels.size(), -1.0f); // a copy would overwrite this
  EXPECT_FALSE(ref.latest(again));
  EXPECT_EQ(again.image.pixels, std::vector<float>(snap.image.pixels.size(), -1.0f));
  // A new generation: the old mean is dropped until the new job's first batch.
  EXPECT_EQ(ref.start(c.scene, c.points, "ao", progressive(8, c.radius, 2)), 2u);
  const ProgressiveSnapshot second = waitConverged(ref);
  EXPECT_EQ(second.generation, 2u);
  EXPECT_NE(second.image.pixels, snap.image.pixels);
}

TEST(ProgressiveReference, RestartIsPromptAndBumpsTheGeneration) {
  // 256x256 points and a target that is never reached, so the worker is always inside a batch:
  // at 16 spp a batch is a million AO rays, a 16x16 tile 4096. start() must return without
  // waiting for the worker at all; stop() waits for at most one tile per thread. The bounds (0.5 s
  // and 2 s) are far above a tile's cost and loose on purpose: the test machine may be shared and
  // loaded, and a descheduled thread must not fail the test. They catch a start() that joins the
  // worker or a cancellation that never reaches the batch loop.
  const test::WallCase c = test::wallCase(256, 256, 0.95f);
  ProgressiveReference ref;
  const std::uint64_t first = ref.start(c.scene, c.points, "ao", progressive(65536, c.radius));
  const auto waitStart = Clock::now();
  while (ref.samples() < 4 && secondsSince(waitStart) < 60.0)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_GE(ref.samples(), 4);
  EXPECT_TRUE(ref.running());

  const auto restart = Clock::now();
  const std::uint64_t second = ref.start(c.scene, c.points, "ao", progressive(65536, c.radius, 9));
  const double startSeconds = secondsSince(restart);
  EXPECT_EQ(second, first + 1);
  EXPECT_EQ(ref.generation(), second);
  EXPECT_EQ(ref.samples(), 0); // the old mean is gone at once
  EXPECT_LT(startSeconds, 0.5) << "start() must not wait for the worker";

  ProgressiveSnapshot snap;
  while (!ref.latest(snap) && secondsSince(restart) < 60.0)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  EXPECT_EQ(snap.generation, second);
  EXPECT_GE(snap.samples, 1);
  RecordProperty("restart_to_first_batch_s", std::to_string(secondsSince(restart)));

  // Stop inside a 16 spp batch (samples 32 -> 48), having timed the previous one (16 -> 32).
  Clock::time_point at16 = restart;
  while (ref.samples() < 32 && secondsSince(restart) < 60.0) {
    if (ref.samples() < 16) at16 = Clock::now();
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  ASSERT_GE(ref.samples(), 32);
  RecordProperty("batch_16spp_s", std::to_string(secondsSince(at16)));
  const auto stop = Clock::now();
  ref.stop();
  const double stopSeconds = secondsSince(stop);
  RecordProperty("stop_s", std::to_string(stopSeconds));
  EXPECT_LT(stopSeconds, 2.0);
  EXPECT_FALSE(ref.running());
  const int samples = ref.samples();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_EQ(ref.samples(), samples); // nothing runs after stop()
}

TEST(ProgressiveReference, CancelReturnsAtOnceAndTheWorkerStopsOnItsOwn) {
  // cancel() is what the viewer calls while the camera moves: it must not wait for the worker
  // (the bound is loose for a loaded machine), and no sample is added once the worker has seen it.
  const test::WallCase c = test::wallCase(256, 256, 0.95f);
  ProgressiveReference ref;
  ref.start(c.scene, c.points, "ao", progressive(65536, c.radius));
  const auto waitStart = Clock::now();
  while (ref.samples() < 4 && secondsSince(waitStart) < 60.0)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_GE(ref.samples(), 4);
  const auto cancel = Clock::now();
  ref.cancel();
  EXPECT_LT(secondsSince(cancel), 0.5) << "cancel() must not wait for the worker";
  EXPECT_FALSE(ref.running());
  ref.stop(); // now waits for the worker to have left the batch
  const int samples = ref.samples();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_EQ(ref.samples(), samples);
}

TEST(ProgressiveReference, RejectsBadInputAtOnceAndCancelsThePreviousJob) {
  Scene s;
  test::addQuad(s, {0, 0, 0}, {20, 0, 0}, {0, 0, -20});
  s.camera.position = {0, 10, 5};
  const SurfaceData points = test::gridSurfaces(
      64, 64, {0, 1, 0}, [](int x, int y) { return glm::vec3(-2.0f + x / 16.0f, 0.0f, -2.0f + y / 16.0f); });
  ProgressiveReference ref;
  const std::uint64_t generation = ref.start(s, points, "ao", progressive(65536, 0.5f));
  EXPECT_TRUE(ref.running());
  auto bad = [&](const std::string& aov, ProgressiveOptions o, std::initializer_list<std::string> parts) {
    test::checkCaught(test::catchError([&] { ref.start(s, points, aov, o); }), ExitCode::Usage, parts);
  };
  bad("color", progressive(16, 0.5f), {"color", "visibility, ao, indirect"});
  bad("visibility", progressive(16, 0.5f), {"light"}); // the scene has no light
  bad("ao", progressive(16, 0.0f), {"ao.radius"});
  bad("ao", progressive(0, 0.5f), {"targetSpp", "1..65536"});
  bad("ao", progressive(65537, 0.5f), {"65537"});
  ProgressiveOptions o = progressive(16, 0.5f);
  o.batchMaxSpp = 0;
  bad("ao", o, {"batchMaxSpp"});
  bad("ao", progressive(16, 0.5f, 1, -1), {"threads"});
  EXPECT_EQ(ref.generation(), generation);
  EXPECT_FALSE(ref.running());
  ref.stop();
  EXPECT_EQ(ref.error(), "");
}

TEST(ProgressiveReference, DeterministicForASeedWhateverTheThreadsAndTheBvhSource) {
  const test::WallCase c = test::wallCase(40, 24, 1.2f); // several 16x16 tiles
  ProgressiveReference a, b;
  a.start(c.scene, c.points, "ao", progressive(16, c.radius, 7, 1));
  b.start(c.scene, c.points, "ao", progressive(16, c.radius, 7, 2));
  const ProgressiveSnapshot one = waitConverged(a), two = waitConverged(b);
  EXPECT_EQ(one.image.pixels, two.image.pixels);
  EXPECT_EQ(one.image.mask, two.image.mask);

  // Reusing the prepared BVH gives the same images.
  const auto prepared = a.preparedScene();
  ASSERT_NE(prepared, nullptr);
  EXPECT_EQ(prepared->triangleCount(), 4u);
  a.start(prepared, c.scene, c.points, "ao", progressive(16, c.radius, 7, 2));
  EXPECT_EQ(a.preparedScene(), prepared);
  EXPECT_EQ(waitConverged(a).image.pixels, one.image.pixels);

  b.start(c.scene, c.points, "ao", progressive(16, c.radius, 8, 2));
  EXPECT_NE(waitConverged(b).image.pixels, one.image.pixels);
}

TEST(ProgressiveReference, EveryAovHasTheSinglePassShape) {
  Scene s;
  test::addQuad(s, {0, 0, 0}, {20, 0, 0}, {0, 0, -20});
  s.camera.position = {0, 10, 5};
  s.lights = {test::directional({0, -1, 0}, 3, 2)};
  SurfaceData points =
      test::gridSurfaces(4, 4, {0, 1, 0}, [](int x, int y) { return glm::vec3(-2.0f + x, 0.0f, -2.0f + y); });
  points.valid[5] = 0;
  for (const char* aov : {"visibility", "ao", "indirect"}) {
    ProgressiveReference ref;
    ref.start(s, points, aov, progressive(4, 0.5f));
    const ProgressiveSnapshot snap = waitConverged(ref);
    ReferenceOptions single;
    single.spp = 4;
    const Image once = renderReference(s, points, aov, single);
    EXPECT_EQ(snap.image.channels, once.channels) << aov;
    EXPECT_EQ(snap.image.mask, once.mask) << aov;
    for (int k = 0; k < snap.image.channels; ++k)
      EXPECT_EQ(snap.image.pixels[5 * std::size_t(once.channels) + k], 0.0f);
  }
}

} // namespace
} // namespace rtlab
