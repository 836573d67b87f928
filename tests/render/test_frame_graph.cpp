// The frame graph's resources, use declarations, barriers, compute passes and compile-time errors
// (docs/frame-graph.md), on a bare graph in the shared context.
#include <gtest/gtest.h>

#include "frame_graph_fixture.h"
#include "gl/debug.h"
#include "gl/program.h"
#include "util/error.h"

#include <numeric>
#include <vector>

namespace rtlab {
namespace {

gl::TextureDesc rgba16f(GLenum target, int width, int height) {
  gl::TextureDesc d;
  d.target = target;
  d.format = GL_RGBA16F;
  d.width = width;
  d.height = height;
  return d;
}

// Level `level`, layer `layer` of a texture as RGBA floats.
std::vector<float> readLayer(const gl::Texture& t, int level, int layer) {
  const gl::TextureDesc& d = t.desc();
  const int w = d.widthAt(level), h = d.heightAt(level);
  std::vector<float> out(std::size_t(w) * h * 4);
  glGetTextureSubImage(t.id(), level, 0, 0, layer, w, h, 1, GL_RGBA, GL_FLOAT, GLsizei(out.size() * sizeof(float)),
                       out.data());
  return out;
}

// Every texel of the layer equals `value` (all four channels).
bool allEqual(const std::vector<float>& texels, const glm::vec4& value) {
  for (std::size_t i = 0; i < texels.size(); i += 4)
    for (int c = 0; c < 4; ++c)
      if (texels[i + std::size_t(c)] != value[c]) return false;
  return true;
}

// ---- a compute pass writes a 3D texture, a fragment pass samples it ----

// The compute pass that stores f(voxel) = vec4(voxel, 16) / 16 into every voxel of `volume`.
void addVolumeFill(FrameGraph& graph, GraphHarness& h, const std::string& name, const gl::TextureDesc& volume,
                   int* runs = nullptr) {
  graph.addComputePass(
      name, ComputeGrid::of("volume"), [&](PassBuilder& b) { b.writeImage("volume", volume, 0); },
      [&h, runs](PassContext& ctx) -> gl::Program& {
        if (runs) ++*runs;
        return h.program({testShader("volume_fill.comp")}).set("uSize", ctx.grid);
      });
}

// The fragment pass that samples the n^3 volume and unfolds it into the n^2 x n texture "unfolded".
void addVolumeUnfold(FrameGraph& graph, GraphHarness& h, int n) {
  graph.addPass(
      "volume.sample",
      [&](PassBuilder& b) {
        b.read("volume");
        b.write("unfolded", rgba16f(GL_TEXTURE_2D, n * n, n));
      },
      [&h, n](PassContext& ctx) {
        ctx.beginFullscreen("volume.sample", {"unfolded"});
        gl::Program& p = h.program({"common/fullscreen.vert", testShader("volume_sample.frag")});
        p.use();
        ctx.texture("volume").bind(0);
        p.set("uVolume", 0).set("uSize", n);
        ctx.common.drawFullscreen();
      });
}

// Texels of "unfolded" that differ from f(voxel).
int wrongUnfoldedTexels(GraphHarness& h, int n) {
  const std::vector<float> pixels = readLayer(*h.pool.find("unfolded"), 0, 0);
  int wrong = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n * n; ++x) {
      const glm::vec4 expected = glm::vec4(float(x % n), float(y), float(x / n), 16.0f) / 16.0f;
      const float* p = &pixels[(std::size_t(y) * n * n + x) * 4];
      if (glm::vec4(p[0], p[1], p[2], p[3]) != expected) ++wrong;
    }
  return wrong;
}

TEST(FrameGraph, ComputeWritesVolumeThatFragmentPassSamples) {
  testContext().makeCurrent();
  drainGlErrors();
  constexpr int n = 16;
  GraphHarness h(n * n, n);
  FrameGraph graph = h.graph();
  gl::TextureDesc volume = rgba16f(GL_TEXTURE_3D, n, n);
  volume.depth = n;
  addVolumeFill(graph, h, "volume.fill", volume);
  addVolumeUnfold(graph, h, n);
  h.runFrame(graph, {"unfolded"});
  EXPECT_EQ(graph.barrierBefore("volume.sample"), GLbitfield(GL_TEXTURE_FETCH_BARRIER_BIT));
  EXPECT_EQ(graph.barrierBefore("volume.fill"), 0u);
  EXPECT_EQ(wrongUnfoldedTexels(h, n), 0) << "texels that differ from f(voxel)";
  EXPECT_EQ(h.pool.find("volume")->desc().bytes(), std::size_t(n) * n * n * 8);
  EXPECT_EQ(drainGlErrors(), 0);
}

// ---- an imported volume outlives frames: baked once, sampled in later frames ----

TEST(FrameGraph, ImportedVolumeIsBakedOnceAndSampledInLaterFrames) {
  testContext().makeCurrent();
  drainGlErrors();
  constexpr int n = 8;
  GraphHarness h(n * n, n);
  gl::TextureDesc volumeDesc = rgba16f(GL_TEXTURE_3D, n, n);
  volumeDesc.depth = n;
  gl::Texture volume(volumeDesc, "test.volume"); // owned by the "technique", not the pool
  int bakes = 0;
  for (int frame = 0; frame < 3; ++frame) {
    FrameGraph graph = h.graph();
    graph.importTexture("volume", volume);
    if (frame == 0) addVolumeFill(graph, h, "volume.bake", volumeDesc, &bakes);
    addVolumeUnfold(graph, h, n);
    h.runFrame(graph, {"unfolded"});
    // The first use in a frame gets its path's barrier: the object may hold an earlier frame's stores.
    EXPECT_EQ(graph.barrierBefore("volume.sample"), GLbitfield(GL_TEXTURE_FETCH_BARRIER_BIT)) << "frame " << frame;
    EXPECT_EQ(wrongUnfoldedTexels(h, n), 0) << "frame " << frame << " samples what the first baked";
  }
  EXPECT_EQ(bakes, 1);
  for (const auto& e : h.pool.entries()) EXPECT_NE(e.name, "volume") << "an imported object is not pool memory";
  EXPECT_EQ(drainGlErrors(), 0);
}

// ---- an atomic-counter append in one pass, read as storage buffers in the next ----

TEST(FrameGraph, AtomicAppendIsReadByTheNextPassAfterAStorageBarrier) {
  testContext().makeCurrent();
  drainGlErrors();
  constexpr unsigned count = 1000; // invocations; multiples of 3 below it are appended
  GraphHarness h(64, 64);
  for (int frame = 0; frame < 2; ++frame) { // the second frame reuses the buffers and must clear the counter
    FrameGraph graph = h.graph();
    graph.addComputePass(
        "append", ComputeGrid::fixed({int(count), 1, 1}),
        [&](PassBuilder& b) {
          b.writeBuffer("items", {gl::BufferKind::Storage, count * 4}, BufferBinding::Storage, 0);
          b.writeBuffer("appended", {gl::BufferKind::AtomicCounter, 4}, BufferBinding::AtomicCounter, 0);
        },
        [&](PassContext& ctx) -> gl::Program& {
          ctx.buffer("appended").clear();
          return h.program({testShader("append.comp")}).set("uCount", count);
        });
    graph.addComputePass(
        "consume", ComputeGrid::fixed({1, 1, 1}),
        [&](PassBuilder& b) {
          b.readBuffer("items", BufferBinding::Storage, 0);
          b.readBuffer("appended", BufferBinding::Storage, 1);
          b.writeBuffer("result", {gl::BufferKind::Storage, 8}, BufferBinding::Storage, 2);
        },
        [&](PassContext&) -> gl::Program& { return h.program({testShader("consume.comp")}); });
    h.runFrame(graph, {"result"});
    EXPECT_EQ(graph.barrierBefore("append"), 0u);
    EXPECT_EQ(graph.barrierBefore("consume"), GLbitfield(GL_SHADER_STORAGE_BARRIER_BIT))
        << barrierBitsName(graph.barrierBefore("consume"));
    EXPECT_EQ(graph.barrierBefore(FrameGraph::kEndOfFrame), GLbitfield(GL_BUFFER_UPDATE_BARRIER_BIT));

    unsigned expectedCount = 0, expectedSum = 0;
    for (unsigned i = 0; i < count; i += 3) {
      ++expectedCount;
      expectedSum += i * i;
    }
    const std::vector<unsigned> result = h.pool.findBuffer("result")->downloadAs<unsigned>();
    ASSERT_EQ(result.size(), 2u);
    EXPECT_EQ(result[0], expectedCount) << "frame " << frame;
    EXPECT_EQ(result[1], expectedSum) << "frame " << frame;
  }
  // Buffers are frame resources: listed and counted like textures.
  std::size_t bytes = 0;
  for (const auto& e : h.pool.entries()) bytes += e.bytes;
  EXPECT_EQ(bytes, std::size_t(count) * 4 + 4 + 8);
  EXPECT_EQ(h.pool.totalBytes(), bytes);
  EXPECT_EQ(drainGlErrors(), 0);
}

TEST(FrameGraph, IndirectDispatchTakesItsGroupCountsFromABufferAfterACommandBarrier) {
  testContext().makeCurrent();
  drainGlErrors();
  GraphHarness h(8, 8);
  constexpr unsigned groups = 5;
  FrameGraph graph = h.graph();
  graph.addComputePass(
      "args", ComputeGrid::fixed({1, 1, 1}),
      [&](PassBuilder& b) { b.writeBuffer("args", {gl::BufferKind::Indirect, 12}, BufferBinding::Storage, 0); },
      [&](PassContext&) -> gl::Program& { return h.program({testShader("write_args.comp")}).set("uGroups", groups); });
  graph.addComputePass(
      "count", ComputeGrid::indirect("args"),
      [&](PassBuilder& b) { b.writeBuffer("invocations", {gl::BufferKind::AtomicCounter, 4}, BufferBinding::AtomicCounter, 0); },
      [&](PassContext& ctx) -> gl::Program& {
        ctx.buffer("invocations").clear();
        return h.program({testShader("count.comp")});
      });
  h.runFrame(graph, {"invocations"});
  EXPECT_EQ(graph.barrierBefore("count"), GLbitfield(GL_COMMAND_BARRIER_BIT)) << barrierBitsName(graph.barrierBefore("count"));
  const std::vector<unsigned> counted = h.pool.findBuffer("invocations")->downloadAs<unsigned>();
  ASSERT_EQ(counted.size(), 1u);
  EXPECT_EQ(counted[0], groups * 64) << "work groups from the buffer times the local size";
  EXPECT_EQ(drainGlErrors(), 0);
}

TEST(FrameGraph, BarrierBitsFollowTheConsumingUse) {
  // One producer, one consumer per use kind: the bit before the consumer is the one that use needs.
  testContext().makeCurrent();
  GraphHarness h(8, 8);
  const gl::TextureDesc image = rgba16f(GL_TEXTURE_2D, 8, 8);
  struct Case {
    std::function<void(PassBuilder&)> use;
    GLbitfield bit;
  };
  const std::vector<Case> cases = {
      {[](PassBuilder& b) { b.read("img"); }, GL_TEXTURE_FETCH_BARRIER_BIT},
      {[](PassBuilder& b) { b.readImage("img", 0); }, GL_SHADER_IMAGE_ACCESS_BARRIER_BIT},
      {[&](PassBuilder& b) { b.write("img", image); }, GL_FRAMEBUFFER_BARRIER_BIT},
      {[](PassBuilder& b) { b.readBack("img"); }, GL_TEXTURE_UPDATE_BARRIER_BIT},
      {[](PassBuilder& b) { b.readBuffer("buf", BufferBinding::Storage, 0); }, GL_SHADER_STORAGE_BARRIER_BIT},
      {[](PassBuilder& b) { b.readBuffer("buf", BufferBinding::AtomicCounter, 0); }, GL_ATOMIC_COUNTER_BARRIER_BIT},
      {[](PassBuilder& b) { b.readIndirect("buf"); }, GL_COMMAND_BARRIER_BIT},
      {[](PassBuilder& b) { b.readBack("buf"); }, GL_BUFFER_UPDATE_BARRIER_BIT},
  };
  for (const Case& c : cases) {
    FrameGraph graph = h.graph();
    graph.addPass("produce", [&](PassBuilder& b) {
      b.writeImage("img", image, 0);
      b.writeBuffer("buf", {gl::BufferKind::Storage, 16}, BufferBinding::Storage, 0);
    }, [](PassContext&) {});
    graph.addPass("consume", [&](PassBuilder& b) {
      c.use(b);
      b.write("out", image);
    }, [](PassContext&) {});
    graph.compile({"out", "img", "buf"}); // all three wanted: both passes are kept whatever the use
    EXPECT_EQ(graph.barrierBefore("consume"), c.bit) << barrierBitsName(graph.barrierBefore("consume")) << " instead of "
                                                     << barrierBitsName(c.bit);
  }
}

TEST(FrameGraph, AttachmentWritesNeedNoBarrier) {
  testContext().makeCurrent();
  GraphHarness h(8, 8);
  FrameGraph graph = h.graph();
  const gl::TextureDesc d = rgba16f(GL_TEXTURE_2D, 8, 8);
  graph.addPass("a", [&](PassBuilder& b) { b.write("x", d); }, [](PassContext&) {});
  graph.addPass("b", [&](PassBuilder& b) { b.read("x"); b.write("y", d); }, [](PassContext&) {});
  graph.compile({"y"});
  EXPECT_TRUE(graph.barriers().empty());
}

// ---- rendering into one level, one array layer, one cube face ----

struct SolidCase {
  GLenum target;
  int levels, layers, level, layer;
};

void renderSolid(const SolidCase& c) {
  testContext().makeCurrent();
  drainGlErrors();
  GraphHarness h(32, 32);
  FrameGraph graph = h.graph();
  gl::TextureDesc d = rgba16f(c.target, 32, 32);
  d.levels = c.levels;
  d.layers = c.target == GL_TEXTURE_2D_ARRAY ? c.layers : 1;
  const glm::vec4 color(1.0f, 0.5f, 0.25f, 1.0f);
  graph.addPass("clear", [&](PassBuilder& b) { b.write("t", d); }, [&](PassContext& ctx) {
    const float zero[4] = {0, 0, 0, 0};
    for (int l = 0; l < d.levels; ++l) glClearTexImage(ctx.texture("t").id(), l, GL_RGBA, GL_FLOAT, zero);
  });
  graph.addPass("solid", [&](PassBuilder& b) { b.writeAttachment("t", d, c.level, c.layer); }, [&](PassContext& ctx) {
    ctx.beginFullscreen("solid", {"t"});
    GLint viewport[4] = {};
    glGetIntegerv(GL_VIEWPORT, viewport);
    EXPECT_EQ(viewport[2], d.widthAt(c.level));
    h.program({"common/fullscreen.vert", testShader("solid.frag")}).set("uColor", color).use();
    ctx.common.drawFullscreen();
  });
  h.runFrame(graph, {"t"});
  const gl::Texture& t = *h.pool.find("t");
  for (int level = 0; level < d.levels; ++level)
    for (int layer = 0; layer < d.layersAt(level); ++layer) {
      const bool target = level == c.level && (c.layer < 0 || layer == c.layer);
      EXPECT_TRUE(allEqual(readLayer(t, level, layer), target ? color : glm::vec4(0.0f)))
          << "level " << level << " layer " << layer << (target ? " should be the colour" : " should be untouched");
    }
  EXPECT_EQ(drainGlErrors(), 0);
}

TEST(FrameGraph, RendersIntoOneMipLevel) { renderSolid({GL_TEXTURE_2D, 4, 1, 2, -1}); }
TEST(FrameGraph, RendersIntoOneArrayLayer) { renderSolid({GL_TEXTURE_2D_ARRAY, 1, 4, 0, 2}); }
TEST(FrameGraph, RendersIntoOneCubeFace) { renderSolid({GL_TEXTURE_CUBE_MAP, 1, 6, 0, 3}); }
TEST(FrameGraph, RendersIntoOneLayerOfOneLevel) { renderSolid({GL_TEXTURE_2D_ARRAY, 3, 3, 1, 1}); }

TEST(FrameGraph, TextureBytesCountEveryLayerSliceAndLevel) {
  gl::TextureDesc d = rgba16f(GL_TEXTURE_2D_ARRAY, 8, 4);
  d.layers = 3;
  d.levels = 2;
  EXPECT_EQ(d.bytes(), std::size_t(8 * 4 * 3 + 4 * 2 * 3) * 8);
  d.target = GL_TEXTURE_3D;
  d.layers = 1;
  d.depth = 4;
  EXPECT_EQ(d.bytes(), std::size_t(8 * 4 * 4 + 4 * 2 * 2) * 8);
  d.target = GL_TEXTURE_CUBE_MAP;
  d.width = d.height = 4;
  d.levels = 1;
  EXPECT_EQ(d.bytes(), std::size_t(4 * 4 * 6) * 8);
}

// ---- compile-time errors ----

std::string compileError(FrameGraph& graph, const std::vector<std::string>& targets) {
  try {
    graph.compile(targets);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::Internal);
    return e.what();
  }
  return "";
}

TEST(FrameGraph, RefusesAReadBeforeTheFirstWrite) {
  testContext().makeCurrent();
  GraphHarness h(8, 8);
  FrameGraph graph = h.graph();
  const gl::TextureDesc d = rgba16f(GL_TEXTURE_2D, 8, 8);
  graph.addPass("early", [&](PassBuilder& b) { b.read("x"); b.write("y", d); }, [](PassContext&) {});
  graph.addPass("late", [&](PassBuilder& b) { b.write("x", d); }, [](PassContext&) {});
  graph.addPass("final", [&](PassBuilder& b) { b.read("x"); b.read("y"); b.write("z", d); }, [](PassContext&) {});
  const std::string message = compileError(graph, {"z"});
  EXPECT_EQ(message, "frame graph: pass 'early' reads 'x' (sampled), which no earlier pass writes");
  EXPECT_EQ(h.pool.entries().size(), 0u) << "nothing is allocated for a refused graph";
}

TEST(FrameGraph, RefusesTwoDescriptionsOfOneResource) {
  testContext().makeCurrent();
  GraphHarness h(8, 8);
  FrameGraph graph = h.graph();
  graph.addPass("first", [&](PassBuilder& b) { b.write("x", rgba16f(GL_TEXTURE_2D, 64, 64)); }, [](PassContext&) {});
  graph.addPass("second", [&](PassBuilder& b) { b.read("x"); b.writeImage("x", rgba16f(GL_TEXTURE_2D, 32, 64), 0); },
                [](PassContext&) {});
  EXPECT_EQ(compileError(graph, {"x"}), "frame graph: pass 'second' describes 'x' differently from pass 'first' (size 32x64 vs 64x64)");

  FrameGraph buffers = h.graph();
  buffers.addPass("a", [&](PassBuilder& b) { b.writeBuffer("b", {gl::BufferKind::Storage, 16}, BufferBinding::Storage, 0); },
                  [](PassContext&) {});
  buffers.addPass("c", [&](PassBuilder& b) { b.writeBuffer("b", {gl::BufferKind::Storage, 32}, BufferBinding::Storage, 0); },
                  [](PassContext&) {});
  EXPECT_EQ(compileError(buffers, {"b"}), "frame graph: pass 'c' describes 'b' differently from pass 'a' (bytes 32 vs 16)");
}

TEST(FrameGraph, RefusesUsesThatDoNotFitTheResource) {
  testContext().makeCurrent();
  GraphHarness h(8, 8);
  FrameGraph layer = h.graph();
  layer.addPass("a", [&](PassBuilder& b) { b.writeAttachment("t", rgba16f(GL_TEXTURE_2D, 8, 8), 0, 1); }, [](PassContext&) {});
  EXPECT_EQ(compileError(layer, {"t"}),
            "frame graph: pass 'a' uses level 0 layer 1 of 't', a 2D texture with 1 levels and 1 layers");

  FrameGraph kind = h.graph();
  kind.addPass("a", [&](PassBuilder& b) { b.writeBuffer("b", {gl::BufferKind::Storage, 16}, BufferBinding::Storage, 0); },
               [](PassContext&) {});
  kind.addPass("c", [&](PassBuilder& b) { b.read("b"); b.write("t", rgba16f(GL_TEXTURE_2D, 8, 8)); }, [](PassContext&) {});
  EXPECT_EQ(compileError(kind, {"t"}), "frame graph: pass 'c' uses buffer 'b' as a texture (sampled)");
}

TEST(FrameGraph, AllowsAnInPlaceWriteWithTheSameDescription) {
  testContext().makeCurrent();
  GraphHarness h(8, 8);
  FrameGraph graph = h.graph();
  const gl::TextureDesc d = rgba16f(GL_TEXTURE_2D, 8, 8);
  graph.addPass("a", [&](PassBuilder& b) { b.write("x", d); }, [](PassContext&) {});
  graph.addPass("b", [&](PassBuilder& b) { b.read("x"); b.write("x", d); }, [](PassContext&) {});
  EXPECT_EQ(compileError(graph, {"x"}), "");
  EXPECT_TRUE(h.pool.has("x"));
}

TEST(FrameGraph, OptionalReadOfALaterWriteIsAbsent) {
  testContext().makeCurrent();
  drainGlErrors();
  GraphHarness h(8, 8);
  FrameGraph graph = h.graph();
  const gl::TextureDesc d = rgba16f(GL_TEXTURE_2D, 8, 8);
  bool sawOptional = true;
  graph.addPass("a", [&](PassBuilder& b) { b.readIfPresent("x"); b.write("y", d); },
                [&](PassContext& ctx) { sawOptional = ctx.has("x"); });
  graph.addPass("b", [&](PassBuilder& b) { b.read("y"); b.write("x", d); }, [](PassContext&) {});
  h.runFrame(graph, {"x"});
  EXPECT_FALSE(sawOptional);
  EXPECT_EQ(drainGlErrors(), 0);
}

TEST(FrameGraph, ComputeGridMustComeFromADeclaredTexture) {
  testContext().makeCurrent();
  GraphHarness h(8, 8);
  FrameGraph graph = h.graph();
  const gl::TextureDesc d = rgba16f(GL_TEXTURE_2D, 8, 8);
  graph.addPass("a", [&](PassBuilder& b) { b.write("x", d); }, [](PassContext&) {});
  graph.addComputePass("c", ComputeGrid::of("x"), [&](PassBuilder& b) { b.writeImage("y", d, 0); },
                       [&](PassContext&) -> gl::Program& { return h.program({testShader("volume_fill.comp")}); });
  EXPECT_EQ(compileError(graph, {"y"}),
            "frame graph: compute pass 'c' takes its grid from 'x', which it does not declare as a texture it uses");
}

TEST(FrameGraph, CulledComputePassIsNotRun) {
  testContext().makeCurrent();
  GraphHarness h(8, 8);
  FrameGraph graph = h.graph();
  const gl::TextureDesc d = rgba16f(GL_TEXTURE_2D, 8, 8);
  bool ran = false;
  graph.addComputePass("unused", ComputeGrid::frame(), [&](PassBuilder& b) { b.writeImage("u", d, 0); },
                       [&](PassContext&) -> gl::Program& {
                         ran = true;
                         return h.program({testShader("volume_fill.comp")});
                       });
  graph.addPass("used", [&](PassBuilder& b) { b.write("x", d); }, [](PassContext&) {});
  h.runFrame(graph, {"x"});
  EXPECT_FALSE(ran);
  EXPECT_FALSE(h.pool.has("u"));
  const auto passes = graph.passes();
  ASSERT_EQ(passes.size(), 2u);
  EXPECT_TRUE(passes[0].compute);
  EXPECT_FALSE(passes[0].kept);
}

TEST(FrameGraph, RefusesAWriteThatRedescribesAnImportAndADoubleImport) {
  testContext().makeCurrent();
  GraphHarness h(8, 8);
  const gl::TextureDesc d = rgba16f(GL_TEXTURE_2D, 8, 8);
  gl::Texture owned(d, "test.owned");
  {
    FrameGraph graph = h.graph();
    graph.importTexture("owned", owned);
    graph.addPass("resize", [&](PassBuilder& b) { b.write("owned", rgba16f(GL_TEXTURE_2D, 4, 8)); }, [](PassContext&) {});
    EXPECT_EQ(compileError(graph, {"owned"}),
              "frame graph: pass 'resize' describes 'owned' differently from the imported object (size 4x8 vs 8x8)");
  }
  {
    FrameGraph graph = h.graph();
    graph.importTexture("owned", owned);
    try {
      graph.importTexture("owned", owned);
      ADD_FAILURE() << "a second import of one name was accepted";
    } catch (const Error& e) {
      EXPECT_STREQ(e.what(), "frame graph: 'owned' is imported twice");
    }
  }
}

} // namespace
} // namespace rtlab
