// viewer/reference_job: compare mode's one-shot reference worker, on a synthetic reference whose
// compute function waits at a gate the test opens. start() returns while the computation runs;
// the result is the compute function's, from the inputs given; a job superseded or cancelled
// while it computes publishes nothing and of several pending jobs only the newest runs; a failure
// belongs to its generation; missing inputs throw at once; a superseded or cancelled computation,
// and one the destructor outlives, is told to stop (ReferenceFrame::cancelled) and stops.
#include "viewer/reference_job.h"
#include "scene/scene_params.h"
#include "util/error.h"

#include "test_util.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace rtlab {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// Holds every computation until open(); records the value each computation read.
struct Gate {
  std::mutex mutex;
  std::condition_variable cv;
  bool isOpen = false;
  std::vector<float> seen; // the colour's first value, per computation started
  std::atomic<int> finished{0};

  void open() {
    std::lock_guard lock(mutex);
    isOpen = true;
    cv.notify_all();
  }
  // Until open(), or until the frame is cancelled: then Error(Interrupted), as a compute function
  // that honours cancellation does.
  void wait(const ReferenceFrame& frame) {
    std::unique_lock lock(mutex);
    while (!isOpen) {
      if (frame.cancelled()) throw Error(ExitCode::Interrupted, "cancelled at the gate");
      cv.wait_for(lock, std::chrono::milliseconds(2));
    }
  }
  std::size_t started() {
    std::lock_guard lock(mutex);
    return seen.size();
  }
};

// A reference of the colour before post that doubles it, after the gate opens; a colour whose first
// value is negative makes it throw.
ReferenceEntry doublingEntry(std::shared_ptr<Gate> gate) {
  ReferenceEntry e;
  e.aov = "doubled";
  e.stage = "post";
  e.channels = 3;
  e.inputs = {FrameInput::PrePostColor};
  e.compute = [gate](const ReferenceFrame& frame, ReferenceStats&) {
    const Image& color = frame.prePostColor();
    {
      std::lock_guard lock(gate->mutex);
      gate->seen.push_back(color.pixels[0]);
    }
    struct Finish {
      Gate& g;
      ~Finish() { ++g.finished; }
    } finish{*gate};
    gate->wait(frame);
    if (color.pixels[0] < 0.0f) throw Error(ExitCode::Internal, "negative colour");
    Image out(color.width, color.height, 3);
    for (std::size_t i = 0; i < out.pixels.size(); ++i) out.pixels[i] = 2.0f * color.pixels[i];
    return out;
  };
  return e;
}

ReferenceJobInput input(const ReferenceEntry& entry, float value) {
  ReferenceJobInput in{entry, Scene{}, ParamSet{}, 1, 1, std::nullopt, Image(4, 3, 3), std::nullopt, std::nullopt};
  for (float& p : in.prePostColor->pixels) p = value;
  return in;
}

// Polls `done` for up to 30 s (a failure, not a hang).
template <class F> bool eventually(F done) {
  const auto start = Clock::now();
  while (!done()) {
    if (secondsSince(start) > 30.0) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return true;
}

TEST(ReferenceJob, StartReturnsWhileItComputesAndPublishesTheComputeFunctionsImage) {
  auto gate = std::make_shared<Gate>();
  const ReferenceEntry entry = doublingEntry(gate);
  ReferenceJob job;
  ReferenceJobResult result;
  const auto before = Clock::now();
  EXPECT_EQ(job.start(input(entry, 0.25f)), 1u);
  EXPECT_LT(secondsSince(before), 1.0);
  ASSERT_TRUE(eventually([&] { return gate->started() == 1; }));
  EXPECT_TRUE(job.running());
  EXPECT_FALSE(job.latest(result)); // still at the gate
  gate->open();
  ASSERT_TRUE(eventually([&] { return job.latest(result); }));
  EXPECT_FALSE(job.running());
  EXPECT_EQ(result.generation, 1u);
  EXPECT_EQ(result.samples, 1);
  EXPECT_GE(result.seconds, 0.0);
  ASSERT_EQ(result.image.width, 4);
  ASSERT_EQ(result.image.height, 3);
  for (float p : result.image.pixels) EXPECT_EQ(p, 0.5f);
  EXPECT_FALSE(job.latest(result)); // nothing new
  EXPECT_EQ(job.error(), "");
}

TEST(ReferenceJob, ASupersededJobPublishesNothingAndOnlyTheNewestPendingJobRuns) {
  auto gate = std::make_shared<Gate>();
  const ReferenceEntry entry = doublingEntry(gate);
  ReferenceJob job;
  job.start(input(entry, 1.0f));
  ASSERT_TRUE(eventually([&] { return gate->started() == 1; }));
  job.start(input(entry, 2.0f)); // replaced by the next before the worker is free
  EXPECT_EQ(job.start(input(entry, 3.0f)), 3u);
  gate->open();
  ReferenceJobResult result;
  ASSERT_TRUE(eventually([&] { return job.latest(result); }));
  EXPECT_EQ(result.generation, 3u);
  EXPECT_EQ(result.image.pixels[0], 6.0f);
  std::lock_guard lock(gate->mutex);
  EXPECT_EQ(gate->seen, (std::vector<float>{1.0f, 3.0f}));
}

TEST(ReferenceJob, CancelStopsTheComputationInProgressAndDropsIt) {
  auto gate = std::make_shared<Gate>();
  const ReferenceEntry entry = doublingEntry(gate);
  ReferenceJob job;
  job.start(input(entry, 1.0f));
  ASSERT_TRUE(eventually([&] { return gate->started() == 1; }));
  job.cancel();
  EXPECT_FALSE(job.running());
  // The computation sees the cancel flag and stops without the gate opening.
  ASSERT_TRUE(eventually([&] { return gate->finished == 1; }));
  gate->open();
  std::this_thread::sleep_for(std::chrono::milliseconds(50)); // the worker publishes right after
  ReferenceJobResult result;
  EXPECT_FALSE(job.latest(result));
  EXPECT_FALSE(job.running());
}

TEST(ReferenceJob, AFailureBelongsToItsGeneration) {
  auto gate = std::make_shared<Gate>();
  gate->open();
  const ReferenceEntry entry = doublingEntry(gate);
  ReferenceJob job;
  job.start(input(entry, -1.0f));
  ASSERT_TRUE(eventually([&] { return !job.running(); }));
  EXPECT_NE(job.error().find("negative colour"), std::string::npos) << job.error();
  ReferenceJobResult result;
  EXPECT_FALSE(job.latest(result));
  job.start(input(entry, 1.0f));
  EXPECT_EQ(job.error(), "");
  ASSERT_TRUE(eventually([&] { return job.latest(result); }));
  EXPECT_EQ(result.image.pixels[0], 2.0f);
}

TEST(ReferenceJob, MissingInputsAndAnSppOutOfRangeThrowAtOnce) {
  auto gate = std::make_shared<Gate>();
  const ReferenceEntry entry = doublingEntry(gate);
  ReferenceJob job;
  ReferenceJobInput noColor = input(entry, 1.0f);
  noColor.prePostColor.reset();
  EXPECT_RTLAB_ERROR(job.start(noColor), ExitCode::Internal, "doubled", "colour before post");
  ReferenceJobInput surfaces = input(entry, 1.0f);
  surfaces.entry.inputs = {FrameInput::PrePostColor, FrameInput::SurfacePoints};
  EXPECT_RTLAB_ERROR(job.start(surfaces), ExitCode::Internal, "doubled", "surface points");
  ReferenceJobInput spp = input(entry, 1.0f);
  spp.spp = 2;
  EXPECT_RTLAB_ERROR(job.start(spp), ExitCode::Usage, "spp 2", "1..1");
  EXPECT_EQ(job.generation(), 0u);
  EXPECT_FALSE(job.running());
}

TEST(ReferenceJob, TheDestructorCancelsAComputationInProgressAndWaitsForIt) {
  auto gate = std::make_shared<Gate>();
  const ReferenceEntry entry = doublingEntry(gate);
  Clock::time_point before;
  {
    ReferenceJob job;
    job.start(input(entry, 1.0f));
    ASSERT_TRUE(eventually([&] { return gate->started() == 1; }));
    before = Clock::now();
  }
  // Returned promptly although the gate never opened: the computation was told to stop, and it
  // had stopped when the destructor returned.
  EXPECT_LT(secondsSince(before), 1.0);
  EXPECT_EQ(gate->finished, 1);
}

TEST(ReferenceJob, TheSceneHasTheParametersLightsAndCameraAndMaterialsOnlyWhenDeclared) {
  Scene scene;
  scene.materials.resize(1);
  scene.materials[0].baseColor = glm::vec4(0.2f);
  ParamSet params;
  params.declare(sceneParamSpecs(scene));
  params.set("camera.fov", ParamValue::scalar(30.0));
  ReferenceEntry e;
  e.inputs = {FrameInput::PrePostColor};
  const Scene plain = sceneForReference(scene, params, e);
  EXPECT_EQ(plain.camera.fovY, 30.0f);
  EXPECT_EQ(plain.materials[0].baseColor, Material{}.baseColor);
  e.inputs = {FrameInput::PrePostColor, FrameInput::Materials};
  EXPECT_EQ(sceneForReference(scene, params, e).materials[0].baseColor, glm::vec4(0.2f));
}

} // namespace
} // namespace rtlab
