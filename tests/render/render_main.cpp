// The render-test binary's main: creates the shared headless context before any test runs.
#include "render_fixture.h"

#include "frame/param_catalog.h"
#include "frame/registry.h"
#include "frame/selection.h"
#include "frame/frame_graph.h"
#include "frame/frame_view.h"
#include "gl/debug.h"
#include "gl_error_check.h"
#include "scene/load.h"
#include "scene/scene_params.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>

namespace rtlab {
namespace {
std::unique_ptr<Context> g_context;
std::map<std::string, std::unique_ptr<Renderer>> g_renderers;
} // namespace

ResolvedFrame resolvedOf(const TestFrame& frame) {
  ResolvedFrame resolved;
  resolved.options.width = frame.width;
  resolved.options.height = frame.height;
  resolved.scene = frame.scene;
  resolved.params = frame.params;
  resolved.techniques = frame.techniques;
  return resolved;
}

void releaseTestRenderers() { g_renderers.clear(); }

Context& testContext() { return *g_context; }

TestFrame makeTestFrame(const std::string& scene, const std::string& techniques, const std::vector<std::string>& sets,
                        int width, int height) {
  TestFrame f;
  f.scene = loadScene(scene);
  f.params = makeParamSet(f.scene, TechniqueRegistry::instance());
  TechniqueSelection sel(TechniqueRegistry::instance());
  if (!techniques.empty()) sel.activateList(techniques);
  f.techniques = sel.ordered();
  for (const auto& s : sets) f.params.setAssignment(s);
  applySceneParams(f.params, f.scene);
  f.width = width;
  f.height = height;
  return f;
}

TestRender renderTestFrame(const TestFrame& frame, const std::vector<std::string>& aovs, bool displayColor, int frames) {
  // One renderer per scene for the whole binary: its program cache saves the shader JIT time.
  auto& renderer = g_renderers[frame.scene.name];
  if (!renderer) {
    renderer = std::make_unique<Renderer>(TechniqueRegistry::instance());
    renderer->setScene(frame.scene);
  }
  TestRender r;
  r.renderer = renderer.get();
  r.renderer->setTechniques(frame.techniques);
  drainGlErrors();
  PassTimer timer(TimingMethod::CpuFinish);
  FrameOutputs outputs{aovs, displayColor};
  for (int i = 0; i < frames; ++i) {
    r.renderer->render(frame.params, frame.width, frame.height, outputs, timer);
    const int errors = drainGlErrors();
    r.glErrors += errors;
    r.stats.addFrame(timer, errors);
  }
  r.stats.setResources(r.renderer->resources());
  return r;
}

void renderOwnFrame(Renderer& renderer, const ParamSet& params, const std::vector<std::string>& techniques,
                    const FrameOutputs& outputs, int width, int height) {
  testContext().makeCurrent();
  renderer.setTechniques(techniques);
  drainGlErrors();
  PassTimer timer(TimingMethod::CpuFinish);
  renderer.render(params, width, height, outputs, timer);
  EXPECT_EQ(drainGlErrors(), 0);
}

double techniqueCounter(const Renderer& renderer, const std::string& technique, const std::string& name) {
  for (const auto& c : renderer.counters())
    if (c.technique == technique && c.name == name) return c.value;
  ADD_FAILURE() << "no " << technique << " counter " << name;
  return -1;
}

bool projectToPixel(const TestFrame& frame, const glm::vec3& world, int& x, int& y) {
  const FrameView view = makeFrameView(frame.scene.camera, frame.width, frame.height);
  const glm::vec4 clip = view.viewProj * glm::vec4(world, 1.0f);
  if (clip.w <= 0.0f) return false;
  const glm::vec3 ndc = glm::vec3(clip) / clip.w;
  x = int((ndc.x * 0.5f + 0.5f) * float(frame.width));
  y = frame.height - 1 - int((ndc.y * 0.5f + 0.5f) * float(frame.height));
  return x >= 0 && x < frame.width && y >= 0 && y < frame.height;
}

bool hasResource(const Renderer& renderer, const std::string& prefix) {
  for (const auto& r : renderer.resources())
    if (r.name.rfind(prefix, 0) == 0) return true;
  return false;
}

bool ranPass(const Renderer& renderer, const std::string& prefix) {
  for (const auto& p : renderer.lastPasses())
    if (p.kept && p.name.rfind(prefix, 0) == 0) return true;
  return false;
}

} // namespace rtlab

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  // Every GL error fails the test it happened in; the global set-up and teardown are checked here
  // (docs/testing.md "GL errors").
  rtlab::installGlErrorListener();
  const std::int64_t beforeSetUp = rtlab::glErrorTotal();
  try {
    // RTLAB_TEST_BACKEND=egl|osmesa runs the whole binary on one backend (default: auto).
    const char* backend = std::getenv("RTLAB_TEST_BACKEND");
    rtlab::g_context = rtlab::createHeadlessContext(backend ? rtlab::parseBackend(backend) : rtlab::Backend::Auto);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "render tests need a GL 4.5 context: %s\n", e.what());
    return 1;
  }
  std::printf("render tests on %s (%s)\n", rtlab::g_context->info().renderer.c_str(),
              rtlab::g_context->backendName().c_str());
  bool clean = rtlab::noGlErrorsOutsideTests("global set-up (context creation)", beforeSetUp);
  // Every frame the tests render checks the GL state before and after each pass (docs/frame-graph.md).
  rtlab::FrameGraph::setStateCheckDefault(true);
  int rc = RUN_ALL_TESTS();
  const std::int64_t beforeTeardown = rtlab::glErrorTotal();
  rtlab::g_context->makeCurrent();
  rtlab::releaseTestRenderers();
  clean = rtlab::noGlErrorsOutsideTests("global teardown (the shared renderers' GL objects)", beforeTeardown) && clean;
  rtlab::g_context.reset();
  rtlab::reportRenderTestGlErrors();
  return clean ? rc : 1;
}
