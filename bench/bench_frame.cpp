// Frame benchmark: per-pass times of a scene (default contact with shadow_map at 1280x720,
// median of 20 frames after 5 warm-up frames) and the floor of a full-screen pass (one texture
// fetch and one RGBA16F write per pixel), timed by the same mechanism as every pass.
//   rtlab_bench [--scene S] [-t IDS] [--size WxH] [--frames N] [--warmup N] [--backend B] [--timing M]
#include "app/frame_options.h"
#include "app/measure.h"
#include "frame/registry.h"
#include "gl/framebuffer.h"
#include "gl/program_cache.h"
#include "render/renderer.h"
#include "shading/gpu_common.h"
#include "util/error.h"

#include <cstdio>
#include <string>

using namespace rtlab;

namespace {

double floorPassMs(gl::ProgramCache& programs, int width, int height, int warmup, int frames, TimingMethod method) {
  gl::TextureDesc d;
  d.format = GL_RGBA16F;
  d.width = width;
  d.height = height;
  gl::Texture src(d, "bench.source"), dst(d, "bench.target");
  const float grey[4] = {0.5f, 0.5f, 0.5f, 1.0f};
  glClearTexImage(src.id(), 0, GL_RGBA, GL_FLOAT, grey);
  GpuCommon common;
  gl::Framebuffer fbo = gl::makeFramebuffer("bench.floor", {&dst});
  gl::Program& p = programs.get({{"common/fullscreen.vert", "bench/one_fetch.frag"}, {}, "bench.one_fetch"});
  PassTimer timer(method);
  std::vector<double> ms;
  for (int i = 0; i < warmup + frames; ++i) {
    timer.beginFrame();
    timer.begin("floor", "");
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glViewport(0, 0, width, height);
    p.use();
    src.bind(0);
    p.set("uSource", 0);
    common.drawFullscreen();
    timer.end();
    timer.endFrame();
    if (i >= warmup) ms.push_back(timer.frameSamples()[0].ms);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return median(ms);
}

} // namespace

int main(int argc, char** argv) {
  try {
    std::vector<OptionSpec> specs = frameOptionSpecs();
    specs.push_back({"--warmup", "", true, "N", "warm-up frames (default 5)"});
    Args args("bench", specs, argc, argv, 1);
    std::vector<char*> patched; // defaults for the benchmark: 1280x720, contact + shadow_map, 20 frames
    ResolvedFrame frame = resolveFrame(args);
    if (!args.has("--size")) frame.options.width = 1280, frame.options.height = 720;
    if (!args.has("--frames")) frame.options.frames = 20;
    if (!args.has("--technique")) frame.techniques = {"shadow_map"};
    const int warmup = args.has("--warmup") ? int(parseIntOption("--warmup", args.get("--warmup"), 0, 1000)) : 5;

    auto context = createHeadlessContext(frame.options.backend);
    const TimingMethod timing = resolveTiming(frame.options.timing, context->info().software);
    Renderer renderer(TechniqueRegistry::instance());
    renderer.setScene(frame.scene);
    FrameOutputs outputs{{}, true};
    // Warm-up beyond the 2 frames renderMeasured adds: JIT, allocation, caches.
    ResolvedFrame warm = frame;
    warm.options.frames = std::max(1, warmup - 2);
    renderMeasured(renderer, warm, outputs, timing, false);
    const FrameStats stats = renderMeasured(renderer, frame, outputs, timing, false);

    std::printf("renderer: %s (%s), timing %s\n", context->info().renderer.c_str(), context->backendName().c_str(),
                timingName(timing));
    std::printf("scene %s, techniques:", frame.options.sceneSpec.c_str());
    for (const auto& t : frame.techniques) std::printf(" %s", t.c_str());
    std::printf(", %dx%d, median of %d frames after %d warm-up\n", frame.options.width, frame.options.height,
                frame.options.frames, warmup);
    std::printf("%-28s %-12s %9s %9s %9s\n", "pass", "technique", "median", "min", "max");
    for (const auto& p : stats.passes())
      std::printf("%-28s %-12s %9.2f %9.2f %9.2f\n", p.name.c_str(), p.technique.empty() ? "-" : p.technique.c_str(), p.ms,
                  p.msMin, p.msMax);
    std::printf("%-28s %-12s %9.2f\n", "frame (wall)", "-", stats.frameMs());
    std::printf("%-28s %-12s %9.2f   (one fetch + one RGBA16F write per pixel)\n", "floor: full-screen pass", "-",
                floorPassMs(renderer.programs(), frame.options.width, frame.options.height, warmup,
                            frame.options.frames, timing));
    std::printf("GPU resources: %.1f MiB, GL errors %d\n", double(stats.resourceBytes()) / double(1 << 20), stats.glErrors());
    return 0;
  } catch (const Error& e) {
    std::fprintf(stderr, "rtlab_bench: error: %s\n", e.what());
    return int(e.code());
  }
}
