// A technique whose stage output comes from a compute pass (the compute example of
// docs/adding-a-technique.md): the image store reaches the lighting and AOV passes through the
// barrier the graph plans from the declarations, and the output is the stage's like any other.
#include "frame/frame_graph.h"
#include "frame/technique.h"
#include "frame_graph_fixture.h"
#include "gl/program_cache.h"
#include "own_registry.h"
#include "shading/base_passes.h"

#include <gtest/gtest.h>

namespace rtlab {
namespace {

class ComputeAo : public Technique {
public:
  explicit ComputeAo(TechniqueInfo info) : m_info(std::move(info)) {}
  const TechniqueInfo& info() const override { return m_info; }
  void setup(FrameGraph& frame) override {
    frame.addComputePass("cao.estimate", ComputeGrid::frame(),
        [&](PassBuilder& b) {
          b.read(res::kGeometry);
          b.writeImage("ao", frameTexture(frame, GL_R16F), 0);
        },
        [](PassContext& ctx) -> gl::Program& {
          ctx.texture(res::kGeometry).bind(0);
          gl::ProgramDesc desc;
          desc.stages = {testShader("quarter_ao.comp")};
          desc.label = "cao.estimate";
          return ctx.programs.get(desc).set("uGeometry", 0);
        });
  }

private:
  TechniqueInfo m_info;
};

class ComputeTechnique : public OwnRegistryTest {
protected:
  void SetUp() override {
    OwnRegistryTest::SetUp();
    addTechnique<ComputeAo>("cao", "ao");
  }
};

TEST_F(ComputeTechnique, ImageStoreIsTheStageOutputThatLightingAndAovRead) {
  load("cornell");
  m_renderer->setTechniques({"cao"});
  FrameOutputs outputs;
  outputs.aovs = {"ao", "color"};
  render(outputs);
  const Image ao = m_renderer->readAov("ao");
  std::size_t surface = 0, wrong = 0;
  for (std::size_t i = 0; i < ao.mask.size(); ++i) {
    if (ao.mask[i] < 0.5f) continue;
    ++surface;
    if (ao.pixels[i] != 0.25f) ++wrong;
  }
  EXPECT_GT(surface, 100u);
  EXPECT_EQ(wrong, 0u) << "surface pixels whose ao is not the compute pass's 0.25";

  bool ranCompute = false;
  for (const auto& p : m_renderer->lastPasses()) ranCompute = ranCompute || (p.name == "cao.estimate" && p.kept);
  EXPECT_TRUE(ranCompute);

  // The ambient term is scaled by ao: the frame is darker with the technique than without it.
  const Image with = m_renderer->readAov("color");
  m_renderer->setTechniques({});
  render(outputs);
  const Image without = m_renderer->readAov("color");
  double sumWith = 0, sumWithout = 0;
  for (std::size_t i = 0; i < with.pixels.size(); ++i) {
    sumWith += with.pixels[i];
    sumWithout += without.pixels[i];
  }
  EXPECT_LT(sumWith, sumWithout);
}

} // namespace
} // namespace rtlab
