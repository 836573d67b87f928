// The known GL state and the frame graph's state check (gl/state.h, docs/frame-graph.md "The known
// state"): a pass that changes every tracked state leaves nothing behind, a leak is named.
#include <gtest/gtest.h>

#include "frame_graph_fixture.h"
#include "frame/pass_timer.h"
#include "gl/debug.h"
#include "gl/program.h"
#include "gl/state.h"
#include "util/error.h"

namespace rtlab {
namespace {

TEST(GlState, RestoreGivesTheKnownState) {
  testContext().makeCurrent();
  gl::restoreKnownState();
  EXPECT_EQ(gl::firstDifference(gl::captureState(), gl::knownState()), "");
  EXPECT_EQ(drainGlErrors(), 0);
}

TEST(GlState, CompareNamesEachFieldThatDiffers) {
  testContext().makeCurrent();
  gl::restoreKnownState();
  const gl::StateSnapshot known = gl::knownState();
  ASSERT_GT(known.fields.size(), 40u);
  for (std::size_t i = 0; i < known.fields.size(); ++i) {
    gl::StateSnapshot changed = gl::captureState();
    changed.fields[i].second += 1;
    const std::string diff = gl::firstDifference(changed, known);
    EXPECT_EQ(diff.rfind(known.fields[i].first + " is ", 0), 0u) << diff;
  }
}

// Changes every tracked piece of state (and checks that it did).
void changeEverything(PassContext& ctx, gl::Program& program, GLuint buffer, GLuint sampler, GLuint fbo) {
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  glFrontFace(GL_CW);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_ONE);
  glBlendEquationSeparate(GL_MAX, GL_FUNC_SUBTRACT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GEQUAL);
  glDepthMask(GL_FALSE);
  glEnable(GL_DEPTH_CLAMP);
  glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
  glColorMaski(3, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(2.0f, 4.0f);
  glEnable(GL_SCISSOR_TEST);
  glEnable(GL_STENCIL_TEST);
  glEnable(GL_RASTERIZER_DISCARD);
  glBindImageTexture(5, ctx.texture("t").id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA16F);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, buffer);
  glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, 0, buffer);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, buffer);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, buffer);
  glBindSampler(7, sampler);
  glActiveTexture(GL_TEXTURE4);
  program.use();
  glBindVertexArray(ctx.common.emptyVao.id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);

  const gl::StateSnapshot now = gl::captureState(), known = gl::knownState();
  int same = 0;
  std::string sameNames;
  for (std::size_t i = 0; i < known.fields.size(); ++i) {
    const std::string& name = known.fields[i].first;
    // Indexed bindings other than the ones set above keep their known value.
    const bool indexed = name.find('[') != std::string::npos;
    const bool setAbove = name == "image_unit[5].texture" || name == "storage_buffer[3].buffer" ||
                          name == "atomic_counter_buffer[0].buffer" || name == "sampler_unit[7].sampler" ||
                          name == "color_mask[0].rgba" || name == "color_mask[3].rgba";
    if (indexed && !setAbove) continue;
    if (now.fields[i].second == known.fields[i].second) {
      ++same;
      sameNames += name + " ";
    }
  }
  EXPECT_EQ(same, 0) << "not changed by the test pass: " << sameNames;
}

TEST(GlState, GraphRestoresEverythingAPassChanges) {
  testContext().makeCurrent();
  drainGlErrors();
  GraphHarness h(16, 16);
  gl::Buffer buffer("state.buffer");
  glNamedBufferStorage(buffer.id(), 64, nullptr, 0);
  gl::Sampler sampler("state.sampler");
  gl::TextureDesc d;
  d.format = GL_RGBA16F;
  d.width = d.height = 16;
  for (int frame = 0; frame < 2; ++frame) {
    FrameGraph graph = h.graph();
    graph.addPass("messy", [&](PassBuilder& b) { b.write("t", d); }, [&](PassContext& ctx) {
      const gl::Framebuffer& fbo = ctx.framebuffer("messy", {"t"});
      changeEverything(ctx, h.program({"common/fullscreen.vert", testShader("solid.frag")}), buffer.id(), sampler.id(),
                       fbo.id());
    });
    graph.addPass("next", [&](PassBuilder& b) { b.read("t"); b.write("u", d); }, [&](PassContext&) {
      EXPECT_EQ(gl::firstDifference(gl::captureState(), gl::knownState()), "") << "the next pass starts from the known state";
    });
    EXPECT_NO_THROW(h.runFrame(graph, {"u"}));
  }
  EXPECT_EQ(gl::firstDifference(gl::captureState(), gl::knownState()), "");
  EXPECT_EQ(drainGlErrors(), 0);
}

TEST(GlState, CheckNamesStateLeftBeforeTheFirstPass) {
  testContext().makeCurrent();
  GraphHarness h(16, 16);
  gl::TextureDesc d;
  d.width = d.height = 16;
  FrameGraph graph = h.graph();
  graph.addPass("a", [&](PassBuilder& b) { b.write("t", d); }, [](PassContext&) {});
  graph.compile({"t"});
  glEnable(GL_BLEND); // leaked by whoever drew before the frame
  PassTimer timer(TimingMethod::CpuFinish);
  timer.beginFrame();
  try {
    graph.run(timer);
    ADD_FAILURE() << "the leaked blend state was not reported";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "frame graph: GL state before the first pass is not the known state: blend.enabled is 1, expected 0");
  }
  gl::restoreKnownState();
  // With the check off the graph starts from the known state anyway.
  glEnable(GL_BLEND);
  FrameGraph unchecked = h.graph();
  unchecked.setStateCheck(false);
  bool blend = true;
  unchecked.addPass("a", [&](PassBuilder& b) { b.write("t", d); }, [&](PassContext&) { blend = glIsEnabled(GL_BLEND); });
  h.runFrame(unchecked, {"t"});
  EXPECT_FALSE(blend);
}

} // namespace
} // namespace rtlab
