// Technique counters (Technique::counters(), docs/cli.md "counters"): what an active technique
// reports about its last frame reaches the stats JSON with its id, in stage order; an inactive
// technique reports nothing.
#include "frame/frame_graph.h"
#include "frame/stats.h"
#include "frame/technique.h"
#include "own_registry.h"

#include <gtest/gtest.h>

namespace rtlab {
namespace {

// Counts its own setup() calls: a value only the technique knows, changing every frame.
class SetupCounter : public Technique {
public:
  explicit SetupCounter(TechniqueInfo info) : m_info(std::move(info)) {}
  const TechniqueInfo& info() const override { return m_info; }
  void setup(FrameGraph&) override { ++m_setups; }
  std::vector<TechniqueCounter> counters() const override { return {{"setups", double(m_setups)}}; }

private:
  TechniqueInfo m_info;
  int m_setups = 0;
};

class TechniqueCounters : public OwnRegistryTest {
protected:
  void SetUp() override {
    OwnRegistryTest::SetUp();
    addTechnique<SetupCounter>("count_post", "post");
    addTechnique<SetupCounter>("count_shadow", "shadow");
  }
};

TEST_F(TechniqueCounters, ActiveTechniquesReportTheirCountsInStageOrder) {
  load("contact");
  FrameOutputs outputs;
  outputs.aovs = {"color"};
  EXPECT_TRUE(m_renderer->counters().empty()) << "no technique active";

  m_renderer->setTechniques({"count_shadow", "count_post"});
  render(outputs, 3);
  const std::vector<CounterValue> counters = m_renderer->counters();
  ASSERT_EQ(counters.size(), 2u);
  EXPECT_EQ(counters[0].technique, "count_shadow");
  EXPECT_EQ(counters[1].technique, "count_post");
  for (const auto& c : counters) {
    EXPECT_EQ(c.name, "setups");
    EXPECT_EQ(c.value, 3.0);
  }

  FrameStats stats;
  stats.setCounters(counters);
  const auto json = stats.toJson();
  ASSERT_EQ(json.at("counters").size(), 2u);
  EXPECT_EQ(json["counters"][0]["technique"], "count_shadow");
  EXPECT_EQ(json["counters"][0]["name"], "setups");
  EXPECT_EQ(json["counters"][0]["value"], 3.0);

  m_renderer->setTechniques({"count_post"}); // count_shadow off: destroyed, reports nothing
  render(outputs);
  ASSERT_EQ(m_renderer->counters().size(), 1u);
  EXPECT_EQ(m_renderer->counters()[0].technique, "count_post");
  EXPECT_EQ(m_renderer->counters()[0].value, 4.0) << "the instance lives on while it stays active";
}

} // namespace
} // namespace rtlab
