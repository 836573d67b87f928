#include "frame_graph_fixture.h"

#include "frame/pass_timer.h"

namespace rtlab {

std::string testShader(const std::string& name) { return std::string(RTLAB_TEST_SHADERS) + "/" + name; }

GraphHarness::GraphHarness(int width, int height) {
  view.width = width;
  view.height = height;
  sceneGpu = std::make_unique<SceneGpu>(scene);
}

FrameGraph GraphHarness::graph() {
  FrameGraph g(scene, params, view, *sceneGpu, programs, pool, common);
  g.setStateCheck(true);
  return g;
}

void GraphHarness::runFrame(FrameGraph& graph, const std::vector<std::string>& targets) {
  graph.compile(targets);
  PassTimer timer(TimingMethod::CpuFinish);
  timer.beginFrame();
  graph.run(timer);
  timer.endFrame();
}

gl::Program& GraphHarness::program(const std::vector<std::string>& stages) {
  gl::ProgramDesc desc;
  desc.stages = stages;
  desc.label = stages.back();
  return programs.get(desc);
}

} // namespace rtlab
