// A bare frame graph in the shared context, without a renderer: an empty scene, default parameters,
// the test shaders under tests/render/shaders (tests/render/test_frame_graph.cpp and friends).
#pragma once
#include "frame/frame_graph.h"
#include "frame/frame_view.h"
#include "frame/resource_pool.h"
#include "gl/program_cache.h"
#include "params/param_set.h"
#include "render_fixture.h"
#include "scene/scene.h"
#include "shading/gpu_common.h"
#include "shading/scene_gpu.h"

#include <memory>
#include <string>

namespace rtlab {

struct GraphHarness {
  Scene scene;
  ParamSet params;
  FrameView view;
  std::unique_ptr<SceneGpu> sceneGpu;
  gl::ProgramCache programs;
  ResourcePool pool;
  GpuCommon common;

  GraphHarness(int width, int height);
  ~GraphHarness() { pool.releaseAll(); }
  // A graph with the state check on.
  FrameGraph graph();
  // Compiles for `targets` and runs one frame (cpu-finish timer).
  void runFrame(FrameGraph& graph, const std::vector<std::string>& targets);
  // A program from test shaders (absolute paths under tests/render/shaders) and shaders/ files.
  gl::Program& program(const std::vector<std::string>& stages);
};

// The absolute path of a test shader.
std::string testShader(const std::string& name);

} // namespace rtlab
