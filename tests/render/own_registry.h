// A renderer over the test's own techniques (a registry of fakes instead of the registered ones),
// with its scene and keys: for tests of what the renderer does to a technique.
#pragma once
#include "frame/param_catalog.h"
#include "frame/registry.h"
#include "params/param_set.h"
#include "render_fixture.h"
#include "scene/load.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace rtlab {

class OwnRegistryTest : public ::testing::Test {
protected:
  void SetUp() override { testContext().makeCurrent(); }

  // Registers technique T, constructed from its TechniqueInfo, as `id` in `stage`.
  template <class T>
  void addTechnique(const std::string& id, const std::string& stage) {
    TechniqueInfo info;
    info.id = id;
    info.stage = stage;
    info.title = id;
    TechniqueEntry e;
    e.info = info;
    e.create = [info] { return std::make_unique<T>(info); };
    m_registry.add(e);
  }

  // Loads a scene, its default keys (scene keys and those of m_registry's techniques, so register
  // them first) and sets it on a new renderer.
  void load(const std::string& name) {
    m_scene = loadScene(name);
    m_params = makeParamSet(m_scene, m_registry);
    m_renderer = std::make_unique<Renderer>(m_registry);
    m_renderer->setScene(m_scene);
  }
  void render(const FrameOutputs& outputs, int frames = 1) {
    PassTimer timer(TimingMethod::CpuFinish);
    for (int i = 0; i < frames; ++i) m_renderer->render(m_params, 32, 32, outputs, timer);
  }

  TechniqueRegistry m_registry;
  Scene m_scene;
  ParamSet m_params;
  std::unique_ptr<Renderer> m_renderer;
};

} // namespace rtlab
