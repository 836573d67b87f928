// The progressive reference's latency and accuracy (bench_progressive.h). The GL part (G-buffer,
// read-back) is done once per AOV and not timed; every time is wall time from start() as the
// viewer would see it, polling latest() every half millisecond.
#include "bench_progressive.h"

#include "app/reference_run.h"
#include "frame/registry.h"
#include "image/metrics.h"
#include "platform/context.h"
#include "reference/live_metrics.h"
#include "reference/progressive_reference.h"
#include "render/renderer.h"
#include "util/error.h"

#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>

using namespace rtlab;
using Clock = std::chrono::steady_clock;

namespace {

double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

struct Progress {
  double first = 0.0, at16 = 0.0, at64 = 0.0;
  Image mean16, mean64;
};

// Polls `ref` (started at t0) until it converges; notes when 16 and 64 spp are first reached.
Progress follow(const ProgressiveReference& ref, Clock::time_point t0) {
  Progress p;
  ProgressiveSnapshot snap;
  while (!snap.converged) {
    if (!ref.latest(snap)) {
      if (!ref.error().empty()) throw Error(ExitCode::Internal, ref.error());
      std::this_thread::sleep_for(std::chrono::microseconds(500));
      continue;
    }
    const double t = secondsSince(t0);
    if (p.first == 0.0) p.first = t;
    if (snap.samples >= 16 && p.mean16.pixels.empty()) p.at16 = t, p.mean16 = snap.image;
    if (snap.samples >= 64 && p.mean64.pixels.empty()) p.at64 = t, p.mean64 = snap.image;
  }
  return p;
}

} // namespace

int runProgressiveBench(const ResolvedFrame& frame, const std::vector<std::string>& aovs, int threads, int truthSpp) {
  const int workers = threads > 0 ? threads : std::max(1, tbb::info::default_concurrency() - 1);
  std::printf("progressive reference: %s %dx%d, target 64 spp, batches <= 16 spp, %d threads (%d cores), "
              "truth %d spp\n",
              frame.scene.name.c_str(), frame.options.width, frame.options.height, workers,
              tbb::info::default_concurrency(), truthSpp);
  std::printf("%-11s %8s %8s %8s %9s | %9s %9s | %11s %12s %11s %12s | %8s\n", "aov", "first s", "16spp s", "64spp s",
              "restart s", "single16", "single64", "rmse prog16", "rmse 1pass16", "rmse prog64", "rmse 1pass64",
              "live ms");
  auto context = createHeadlessContext(frame.options.backend);
  Renderer renderer(TechniqueRegistry::instance());
  renderer.setScene(frame.scene);
  const ReferenceInput input = referenceInput(renderer, frame);
  const Scene& scene = input.scene;
  const SurfaceData& surfaces = input.surfaces;

  for (const std::string& aov : aovs) {
    ProgressiveOptions options;
    options.targetSpp = 64;
    options.batchMaxSpp = 16;
    options.seed = frame.options.seed;
    options.aoRadius = frame.params.getFloat("ao.radius");
    options.threads = workers;
    ProgressiveReference ref;
    const auto t0 = Clock::now();
    ref.start(scene, surfaces, aov, options);
    const Progress p = follow(ref, t0);

    // A restart as after a camera move: the BVH is reused, so only the first batch is waited for.
    ProgressiveOptions again = options;
    again.seed += 1;
    again.targetSpp = 1;
    const auto t1 = Clock::now();
    ref.start(ref.preparedScene(), scene, surfaces, aov, again);
    const double restart = follow(ref, t1).first;

    // Single passes on as many threads (BVH build included, as in the progressive times).
    ReferenceOptions single;
    single.seed = frame.options.seed;
    single.aoRadius = options.aoRadius;
    tbb::task_arena arena(workers);
    Image once16, once64, truth;
    const auto t2 = Clock::now();
    single.spp = 16;
    arena.execute([&] { once16 = renderReference(scene, surfaces, aov, single); });
    const double time16 = secondsSince(t2);
    const auto t3 = Clock::now();
    single.spp = 64;
    arena.execute([&] { once64 = renderReference(scene, surfaces, aov, single); });
    const double time64 = secondsSince(t3);
    single.spp = truthSpp;
    single.seed = frame.options.seed + 1000; // independent of both estimates
    arena.execute([&] { truth = renderReference(scene, surfaces, aov, single); });

    // What the viewer pays per new snapshot for its live figures (RMSE, SSIM, FLIP, ...).
    ProgressiveSnapshot snapshot;
    snapshot.image = p.mean64;
    snapshot.samples = 64;
    snapshot.generation = 1;
    const auto t4 = Clock::now();
    const LiveMetrics live = computeLiveMetrics(once16, snapshot);
    const double liveMs = secondsSince(t4) * 1e3;
    if (!live.ready) throw Error(ExitCode::Internal, "live metrics not ready: " + live.reason);

    std::printf("%-11s %8.3f %8.3f %8.3f %9.3f | %9.3f %9.3f | %11.5f %12.5f %11.5f %12.5f | %8.1f\n", aov.c_str(),
                p.first, p.at16, p.at64, restart, time16, time64, computeMetrics(truth, p.mean16).rmse,
                computeMetrics(truth, once16).rmse, computeMetrics(truth, p.mean64).rmse,
                computeMetrics(truth, once64).rmse, liveMs);
  }
  return 0;
}
