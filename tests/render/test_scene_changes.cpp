// Scene-change notifications (docs/scene-data.md "Scene changes"): a technique hears of a scene set,
// of its own activation and of a light<N>.* key that changes a light exactly once, before its
// setup() of that frame, and never of a camera move, an ambient change or a repeated value.
#include <gtest/gtest.h>

#include "own_registry.h"

#include <memory>
#include <string>
#include <vector>

namespace rtlab {
namespace {

// Events in the order the renderer caused them: "<id>:setup" or "<id>:changed:" + g, m, l for the
// categories that were set.
using EventLog = std::vector<std::string>;

class CountingTechnique : public Technique {
public:
  CountingTechnique(TechniqueInfo info, std::shared_ptr<EventLog> log) : m_info(std::move(info)), m_log(std::move(log)) {}
  const TechniqueInfo& info() const override { return m_info; }
  void setup(FrameGraph&) override { m_log->push_back(m_info.id + ":setup"); }
  void sceneChanged(const SceneChange& change) override {
    m_log->push_back(m_info.id + ":changed:" + (change.geometry ? "g" : "") + (change.materials ? "m" : "") +
                     (change.lights ? "l" : ""));
  }

private:
  TechniqueInfo m_info;
  std::shared_ptr<EventLog> m_log;
};

class SceneChanges : public OwnRegistryTest {
protected:
  void SetUp() override {
    OwnRegistryTest::SetUp();
    for (const char* id : {"count_a", "count_b"}) {
      TechniqueEntry e;
      e.info.id = id;
      e.info.stage = "shadow";
      e.info.title = id;
      e.create = [info = e.info, log = m_log] { return std::make_unique<CountingTechnique>(info, log); };
      m_registry.add(e);
    }
    load("contact"); // two lights: a spot and a point
  }

  // Renders `frames` frames (no outputs: every pass is culled, the techniques' setup still runs)
  // and returns the events they caused.
  EventLog render(int frames = 1) {
    m_log->clear();
    OwnRegistryTest::render(FrameOutputs{}, frames);
    return *m_log;
  }

  std::shared_ptr<EventLog> m_log = std::make_shared<EventLog>();
};

TEST_F(SceneChanges, ActivationNotifiesEverythingOnceBeforeTheFirstSetup) {
  m_renderer->setTechniques({"count_a"});
  EXPECT_EQ(render(3), (EventLog{"count_a:changed:gml", "count_a:setup", "count_a:setup", "count_a:setup"}));
}

TEST_F(SceneChanges, EachSceneSetNotifiesEveryActiveTechniqueOnce) {
  m_renderer->setTechniques({"count_a", "count_b"});
  render();
  for (int set = 0; set < 2; ++set) {
    m_renderer->setScene(m_scene);
    EXPECT_EQ(render(2), (EventLog{"count_a:changed:gml", "count_b:changed:gml", "count_a:setup", "count_b:setup",
                                   "count_a:setup", "count_b:setup"}))
        << "set " << set;
  }
}

TEST_F(SceneChanges, ALightKeyThatChangesALightNotifiesLightsOnce) {
  m_renderer->setTechniques({"count_a"});
  render();
  m_params.setAssignment("light0.intensity=100");
  EXPECT_EQ(render(3), (EventLog{"count_a:changed:l", "count_a:setup", "count_a:setup", "count_a:setup"}));
  m_params.setAssignment("light1.position=-5,4,7"); // another light, another key
  EXPECT_EQ(render(2), (EventLog{"count_a:changed:l", "count_a:setup", "count_a:setup"}));
  m_params.reset("light0.intensity"); // back to the scene's value: a change too
  EXPECT_EQ(render(), (EventLog{"count_a:changed:l", "count_a:setup"}));
}

TEST_F(SceneChanges, CameraAmbientAndRepeatedValuesDoNotNotify) {
  m_renderer->setTechniques({"count_a"});
  render();
  m_params.setAssignment("camera.position=1,5,9");
  m_params.setAssignment("camera.fov=60");
  m_params.setAssignment("scene.ambient=0.5,0.5,0.5");
  EXPECT_EQ(render(2), (EventLog{"count_a:setup", "count_a:setup"}));
  // The values the lights already have, set again.
  m_params.setAssignment("light0.intensity=" + std::to_string(m_scene.lights[0].intensity));
  m_params.setAssignment("light1.position=-5,4,6");
  m_params.reset("light0.direction");
  EXPECT_EQ(render(2), (EventLog{"count_a:setup", "count_a:setup"}));
}

TEST_F(SceneChanges, ALightChangeInTheFrameOfASceneSetIsOneNotification) {
  m_renderer->setTechniques({"count_a"});
  render();
  m_renderer->setScene(m_scene);
  m_params.setAssignment("light0.intensity=100");
  EXPECT_EQ(render(2), (EventLog{"count_a:changed:gml", "count_a:setup", "count_a:setup"}));
}

TEST_F(SceneChanges, ANewlyActivatedTechniqueHearsEverythingAndTheOthersNothing) {
  m_renderer->setTechniques({"count_a"});
  render();
  m_renderer->setTechniques({"count_a", "count_b"});
  EXPECT_EQ(render(), (EventLog{"count_b:changed:gml", "count_a:setup", "count_b:setup"}));
  // Off and on again: a new instance, which hears everything again.
  m_renderer->setTechniques({"count_a"});
  EXPECT_EQ(render(), (EventLog{"count_a:setup"}));
  m_renderer->setTechniques({"count_a", "count_b"});
  EXPECT_EQ(render(), (EventLog{"count_b:changed:gml", "count_a:setup", "count_b:setup"}));
}

} // namespace
} // namespace rtlab
