// Reference throughput (docs/performance.md, "Reference renderer"): rays per second of the CPU
// reference for each AOV, default cornell at 512x512, 64 spp, all cores. For each AOV it reports
// the ray casting alone (BVH build included; median of --repeat runs; also per CPU-second, which
// shared machines disturb less than wall time) and the whole job as
// `rtlab reference` does it in one process: GL context, G-buffer, read-back, ray casting.
//   rtlab_bench_reference [scene and frame options] [--aov A[,A]] [--spp N] [--repeat N] [--threads N]
// With --progressive it measures the viewer's progressive reference instead (bench_progressive.h),
// default cornell at 320x180:
//   rtlab_bench_reference --progressive [scene and frame options] [--aov A[,A]] [--threads N] [--truth-spp N]
#include "bench_progressive.h"

#include "app/frame_options.h"
#include "app/reference_run.h"
#include "frame/registry.h"
#include "platform/context.h"
#include "reference/reference.h"
#include "render/renderer.h"
#include "scene/scene_params.h"
#include "util/error.h"

#include <tbb/global_control.h>
#include <tbb/info.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace rtlab;
using Clock = std::chrono::steady_clock;

namespace {

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  for (std::string item; std::getline(ss, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

} // namespace

int main(int argc, char** argv) {
  try {
    std::vector<OptionSpec> specs = frameOptionSpecs();
    specs.push_back({"--aov", "", true, "A[,A]", "AOVs to measure (default visibility,ao,indirect)"});
    specs.push_back({"--spp", "", true, "N", "samples per pixel (default 64)"});
    specs.push_back({"--repeat", "", true, "N", "ray-casting runs per AOV, median reported (default 3)"});
    specs.push_back({"--threads", "", true, "N", "worker threads (default: all cores; --progressive: all but one)"});
    specs.push_back({"--progressive", "", false, "", "measure the progressive reference (bench_progressive.h)"});
    specs.push_back({"--truth-spp", "", true, "N", "--progressive: samples of the truth image (default 1024)"});
    Args args("bench_reference", specs, argc, argv, 1);
    if (args.help()) {
      std::fputs(formatHelp("rtlab_bench_reference [options]", "CPU reference throughput.", specs).c_str(), stdout);
      return 0;
    }
    ResolvedFrame frame = resolveFrame(args);
    if (!args.has("--scene")) {
      frame = makeResolvedFrame("cornell", "", frame.options);
      frame.options.sceneSpec = "cornell";
    }
    const bool progressive = args.has("--progressive");
    if (!args.has("--size")) frame.options.width = progressive ? 320 : 512, frame.options.height = progressive ? 180 : 512;
    const auto aovs = splitList(args.get("--aov", "visibility,ao,indirect"));
    if (progressive) {
      const int threads = int(parseIntOption("--threads", args.get("--threads", "0"), 0, 1024));
      const int truthSpp =
          int(parseIntOption("--truth-spp", args.get("--truth-spp", "1024"), kReferenceMinSpp, kReferenceMaxSpp));
      return runProgressiveBench(frame, aovs, threads, truthSpp);
    }
    const int spp = int(parseIntOption("--spp", args.get("--spp", "64"), kReferenceMinSpp, kReferenceMaxSpp));
    const int repeat = int(parseIntOption("--repeat", args.get("--repeat", "3"), 1, 100));
    const int threads = int(parseIntOption("--threads", args.get("--threads", "0"), 0, 1024));
    std::unique_ptr<tbb::global_control> limit;
    if (threads > 0) limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
    const int workers = int(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));

    std::printf("reference throughput: %s %dx%d, %d spp, %d threads (%d cores)\n", frame.scene.name.c_str(),
                frame.options.width, frame.options.height, spp, workers, tbb::info::default_concurrency());
    std::printf("%-11s %12s %10s %12s %14s %14s %14s\n", "aov", "rays", "cast s", "Mrays/s", "Mrays/cpu-s",
                "whole job s", "whole Mrays/s");
    for (const std::string& aov : aovs) {
      // The whole job, as one `rtlab reference` process does it.
      const auto jobStart = Clock::now();
      auto context = createHeadlessContext(frame.options.backend);
      Renderer renderer(TechniqueRegistry::instance());
      renderer.setScene(frame.scene);
      ReferenceStats first;
      renderReferenceFrame(renderer, frame, aov, spp, false, first);
      const double jobSeconds = secondsSince(jobStart);

      // Ray casting alone, on the same surfaces, repeated.
      FrameOutputs outputs;
      outputs.surfaces = true;
      PassTimer timer(TimingMethod::CpuFinish);
      renderer.render(frame.params, frame.options.width, frame.options.height, outputs, timer);
      const SurfaceData surfaces = renderer.readSurfaces();
      ReferenceOptions options;
      options.spp = spp;
      options.seed = frame.options.seed;
      options.aoRadius = frame.params.getFloat("ao.radius");
      std::vector<double> seconds, cpuSeconds;
      ReferenceStats stats;
      for (int i = 0; i < repeat; ++i) {
        const std::clock_t cpu0 = std::clock();
        renderReference(frame.scene, surfaces, aov, options, stats);
        cpuSeconds.push_back(double(std::clock() - cpu0) / CLOCKS_PER_SEC);
        seconds.push_back(stats.seconds);
      }
      std::sort(seconds.begin(), seconds.end());
      std::sort(cpuSeconds.begin(), cpuSeconds.end());
      const double median = seconds[seconds.size() / 2], cpuMedian = cpuSeconds[cpuSeconds.size() / 2];
      std::printf("%-11s %12llu %10.3f %12.2f %14.2f %14.3f %14.2f\n", aov.c_str(), (unsigned long long)stats.rays,
                  median, double(stats.rays) / median * 1e-6, double(stats.rays) / cpuMedian * 1e-6, jobSeconds,
                  double(first.rays) / jobSeconds * 1e-6);
    }
    return 0;
  } catch (const Error& e) {
    std::fprintf(stderr, "rtlab_bench_reference: error: %s\n", e.what());
    return int(e.code());
  }
}
