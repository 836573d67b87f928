// Depth peeling — Cass Everitt, "Interactive Order-Independent Transparency", NVIDIA technical
// report 2001, composited front to back with the under operator as in Louis Bavoil and Kevin Myers,
// "Order Independent Transparency with Dual Depth Peeling", NVIDIA 2008 (their front-to-back
// peeling). Each layer k draws the transparent geometry with the fixed-function depth test
// (GL_LESS, depth writes on) into a depth target that starts as the opaque depth, discarding the
// fragments at or in front of layer k-1's depth: the target ends holding the k-th nearest fragment
// of every pixel. Its colour is composited under the layers before it, C += T a C_k, T *= 1 - a_k,
// and the composite writes C + T C_opaque: Over of the front-most `depth_peeling.layers` layers
// (docs/contract.md "Transparency"). Fragments behind the last layer are dropped, or blended in
// order-independently (`depth_peeling.tail`). techniques/depth_peeling/README.md has the details,
// the artifacts and the measured cost.
#include "frame/frame_graph.h"
#include "frame/registry.h"
#include "gl/program_cache.h"
#include "params/param_set.h"
#include "shading/base_passes.h"
#include "shading/gpu_common.h"
#include "shading/hdr_clamp.h"
#include "shading/scene_gpu.h"
#include "techniques/common/transparency/abuffer_error.h"

namespace rtlab {
// Named, not anonymous: the technique sources are compiled in unity batches, where another file's
// anonymous namespace (bloom's kCounts) would be the same one.
namespace depth_peeling {

// Two depth targets, layer k writing kDepth[k % 2] while sampling the other (ping-pong).
constexpr const char* kDepthTargets[2] = {"depth_peeling.depth0", "depth_peeling.depth1"};
constexpr const char* kLayer = "depth_peeling.layer";             // RGBA16F (a C, a) of the layer peeled
constexpr const char* kAccum = "depth_peeling.accum";             // RGBA32F (C, T), under.glsl
constexpr const char* kTailSum = "depth_peeling.tail_sum";        // RGBA32F (sum a C, sum a)
constexpr const char* kTailReveal = "depth_peeling.tail_reveal";  // R32F prod (1 - a)
constexpr const char* kCounts = "depth_peeling.counts";           // fragments behind the last layer
constexpr const char* kLayersView = "depth_peeling.layers";
constexpr const char* kRemainingView = "depth_peeling.remaining";
constexpr int kCountsBinding = 0; // shaders/depth_peeling/peel.frag
// shaders/depth_peeling/peel.frag: texture units after SceneGpu's material units 0-4.
constexpr GLuint kPreviousDepthUnit = 5, kOpaqueDepthUnit = 6;
// peel.frag's uMode.
enum PeelMode { kFirstLayer = 0, kLaterLayer = 1, kTail = 2, kRemaining = 3 };

std::string layerPassName(int k) { return "depth_peeling.layer" + std::to_string(k); }

// The program of every draw of the transparent geometry (one source, so the fragments' depths
// agree between passes); `defines` only on the counting frame.
gl::Program& peelProgram(PassContext& ctx, const std::vector<std::string>& defines) {
  gl::Program& p = ctx.programs.get({{"shading/surface.vert", "depth_peeling/peel.frag"}, defines, "depth_peeling.peel"});
  p.use();
  setLayerUniforms(p, ctx);
  return p;
}

// The state of a pass that draws the transparent geometry: no culling (layers are two-sided
// surfaces and each side is a fragment), viewport over the frame.
void beginGeometry(const PassContext& ctx, const gl::Framebuffer& fbo) {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glViewport(0, 0, ctx.view.width, ctx.view.height);
  glDisable(GL_CULL_FACE);
}

class DepthPeeling final : public Technique {
public:
  static TechniqueInfo staticInfo() {
    TechniqueInfo info;
    info.id = "depth_peeling";
    info.stage = "transparency";
    info.title = "Depth peeling (Everitt 2001; front to back, Bavoil & Myers 2008)";
    info.summary = "Peels the nearest transparent layers one pass each with the depth test and composites them "
                   "front to back: exact Over of the front-most `layers` layers, cost proportional to the layers";
    info.showcaseScene = "layers";
    info.params = {
        ParamSpec::integer("depth_peeling.layers", "Layers", 8, 1, 64)
            .withHelp("Layers peeled (one geometry pass each): the front-most layers of every pixel are composited "
                      "exactly; what lies behind the last one is handled by the tail"),
        ParamSpec::choice("depth_peeling.tail", "Tail", {"drop", "blend"}, 0)
            .withFlags(kParamRealloc)
            .withHelp("Fragments behind the last layer: drop (lost, the opaque colour shows through), or blend "
                      "(one more pass: their alpha-weighted average with coverage 1 - prod(1 - a), an approximation)"),
    };
    info.debugViews = {
        {kLayersView, 1, "layers peeled per pixel (the fragments composited exactly, at most depth_peeling.layers)"},
        {kRemainingView, 1,
         "transparent fragments per pixel behind the last layer and in front of the opaque surface (dropped, or "
         "the tail's approximation)"},
        {AbufferError::viewName("depth_peeling"), 1, AbufferError::viewHelp()},
    };
    return info;
  }
  const TechniqueInfo& info() const override { return m_info; }

  void setup(FrameGraph& frame) override {
    const ParamSet& params = frame.params();
    const int layers = params.getInt("depth_peeling.layers");
    const bool blend = params.getEnumName("depth_peeling.tail") == "blend";
    const bool counting = frame.isImported(HdrClampCounters::kResource);
    if (counting) {
      if (!m_counts) m_counts = gl::BufferObject({gl::BufferKind::Storage, sizeof(GLuint)}, kCounts);
      frame.importBuffer(kCounts, m_counts);
    }
    m_countPending = counting;
    m_countValid = false;
    m_blend = blend;
    for (int k = 0; k < layers; ++k) {
      addLayerPass(frame, k, counting && k == 0);
      addUnderPass(frame, k);
      addLayerCountPass(frame, k);
    }
    const std::string last = kDepthTargets[(layers - 1) % 2];
    // The tail pass runs for the blend and, on the counting frame, to count what lies behind the
    // last layer (the composite then declares its targets without using them, to keep the pass).
    const bool tail = blend || counting;
    if (tail) addTailPass(frame, last, counting);
    addRemainingView(frame, last, counting);
    addComposite(frame, tail, blend);
    m_error.add(frame, "depth_peeling", frame.colorOutput());
  }

  // A new scene (geometry set): the last count is about another scene, and the counter buffer goes,
  // so that a scene where the stage does not run holds nothing of depth_peeling.
  void sceneChanged(const SceneChange& change) override {
    if (!change.geometry) return;
    m_counts = gl::BufferObject();
    m_countValid = false;
    m_error.release();
  }

  std::size_t ownedBytes() const override { return (m_counts ? sizeof(GLuint) : 0) + m_error.ownedBytes(); }

  std::vector<TechniqueCounter> counters() const override {
    std::vector<TechniqueCounter> out;
    if (m_countValid && m_counts) {
      glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
      const double remaining = double(m_counts.downloadAs<GLuint>()[0]);
      out.push_back({"remaining_fragments", remaining});
      out.push_back({"dropped_fragments", m_blend ? 0.0 : remaining});
    }
    return out;
  }

private:
  AbufferError m_error; // the debug view <id>.error
  static gl::TextureDesc depthDesc(const FrameGraph& frame) { return frameTexture(frame, GL_DEPTH_COMPONENT32F); }

  // depth_peeling.layer<k>: the depth target starts as a copy of the opaque depth, so that nothing
  // behind an opaque surface is peeled and an empty layer keeps the opaque depth (the next layer's
  // peel test then rejects everything there too); the colour target starts at 0 (empty layer).
  void addLayerPass(FrameGraph& frame, int k, bool countClamp) {
    const std::string name = layerPassName(k);
    const std::string target = kDepthTargets[k % 2];
    const std::string previous = k > 0 ? kDepthTargets[(k - 1) % 2] : "";
    frame.addPass(name,
        [&](PassBuilder& b) {
          b.read(res::kDepth);
          if (!previous.empty()) b.read(previous);
          b.write(target, depthDesc(frame));
          b.write(kLayer, frameTexture(frame, GL_RGBA16F));
          if (countClamp) HdrClampCounters::declareUse(frame, b);
        },
        [=](PassContext& ctx) {
          const gl::Texture& opaque = ctx.texture(res::kDepth);
          glCopyImageSubData(opaque.id(), GL_TEXTURE_2D, 0, 0, 0, 0, ctx.texture(target).id(), GL_TEXTURE_2D, 0, 0, 0,
                             0, opaque.desc().width, opaque.desc().height, 1);
          const gl::Framebuffer& fbo = ctx.framebuffer("depth_peeling.layer", {kLayer}, target);
          beginGeometry(ctx, fbo);
          const float zero[4] = {0, 0, 0, 0};
          glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, zero);
          glEnable(GL_DEPTH_TEST);
          glDepthFunc(GL_LESS);
          glDepthMask(GL_TRUE);
          std::vector<std::string> defines;
          if (countClamp) defines.push_back("HDR_CLAMP_COUNT");
          gl::Program& p = peelProgram(ctx, defines);
          // Counted once per fragment: layer 0 shades every fragment, later layers shade them again.
          if (countClamp) ctx.common.hdrClamp.bind(p, name);
          if (!previous.empty()) ctx.texture(previous).bind(kPreviousDepthUnit);
          p.set("uMode", previous.empty() ? int(kFirstLayer) : int(kLaterLayer));
          ctx.sceneGpu.draw(p, SceneGpu::Filter::Transparent, true, ctx.view.cameraPosition);
        });
  }

  // depth_peeling.under<k>: layer k composited under the accumulation (under.comp).
  void addUnderPass(FrameGraph& frame, int k) {
    const bool first = k == 0;
    frame.addComputePass("depth_peeling.under" + std::to_string(k), ComputeGrid::frame(),
        [&](PassBuilder& b) {
          b.read(kLayer);
          if (first) b.writeImage(kAccum, frameTexture(frame, GL_RGBA32F), 0);
          else b.readWriteImage(kAccum, 0);
        },
        [first](PassContext& ctx) -> gl::Program& {
          gl::Program& p = ctx.programs.get({{"depth_peeling/under.comp"}, {}, "depth_peeling.under"});
          ctx.texture(kLayer).bind(0);
          p.use();
          p.set("uLayer", 0).set("uFirst", first).set("uSize", glm::ivec2(ctx.view.width, ctx.view.height));
          return p;
        });
  }

  // The view depth_peeling.layers: one count pass after each layer (culled unless requested).
  void addLayerCountPass(FrameGraph& frame, int k) {
    const bool first = k == 0;
    const std::string depth = kDepthTargets[k % 2];
    const std::string view = aovResource(kLayersView);
    frame.addComputePass("depth_peeling.count" + std::to_string(k), ComputeGrid::frame(),
        [&](PassBuilder& b) {
          b.read(depth);
          b.read(res::kDepth);
          if (first) b.writeImage(view, frameTexture(frame, GL_RGBA32F), 0);
          else b.readWriteImage(view, 0);
        },
        [=](PassContext& ctx) -> gl::Program& {
          gl::Program& p = ctx.programs.get({{"depth_peeling/count_layers.comp"}, {}, "depth_peeling.count"});
          ctx.texture(depth).bind(0);
          ctx.texture(res::kDepth).bind(1);
          p.use();
          p.set("uLayerDepth", 0).set("uOpaqueDepth", 1).set("uFirst", first)
              .set("uSize", glm::ivec2(ctx.view.width, ctx.view.height));
          return p;
        });
  }

  // Binds what peel.frag's tail modes sample: the last layer's depth and the opaque depth.
  static void bindTailDepths(PassContext& ctx, gl::Program& p, const std::string& last, PeelMode mode) {
    ctx.texture(last).bind(kPreviousDepthUnit);
    ctx.texture(res::kDepth).bind(kOpaqueDepthUnit);
    p.set("uMode", int(mode));
  }

  // On the counting frame, the first of the tail pass and the remaining view to run (whichever the
  // requested outputs keep) counts the fragments behind the last layer: it zeroes the counter and
  // gets peel.frag's COUNT_REMAINING. Without either, counters() reports no count for the frame.
  std::vector<std::string> takeCount(PassContext& ctx, bool counting) {
    if (!counting || !m_countPending) return {};
    m_countPending = false;
    m_countValid = true;
    ctx.buffer(kCounts).clear();
    return {"COUNT_REMAINING"};
  }

  // depth_peeling.tail: every fragment behind the last layer, in front of the opaque surface, adds
  // (a C, a) into tail_sum and multiplies tail_reveal by (1 - a); both blends are commutative,
  // so the draw order does not matter. On the counting frame it also counts the fragments.
  void addTailPass(FrameGraph& frame, const std::string& last, bool counting) {
    frame.addPass("depth_peeling.tail",
        [&](PassBuilder& b) {
          b.read(last);
          b.read(res::kDepth);
          b.write(kTailSum, frameTexture(frame, GL_RGBA32F));
          b.write(kTailReveal, frameTexture(frame, GL_R32F));
          if (counting) b.readWriteBuffer(kCounts, BufferBinding::Storage, kCountsBinding);
        },
        [=, this](PassContext& ctx) {
          const std::vector<std::string> defines = takeCount(ctx, counting);
          const gl::Framebuffer& fbo = ctx.framebuffer("depth_peeling.tail", {kTailSum, kTailReveal});
          beginGeometry(ctx, fbo);
          const float zero[4] = {0, 0, 0, 0}, one[4] = {1, 1, 1, 1};
          glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, zero);
          glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 1, one);
          glEnable(GL_BLEND);
          glBlendFunci(0, GL_ONE, GL_ONE);
          glBlendFunci(1, GL_ZERO, GL_ONE_MINUS_SRC_COLOR);
          gl::Program& p = peelProgram(ctx, defines);
          bindTailDepths(ctx, p, last, kTail);
          ctx.sceneGpu.draw(p, SceneGpu::Filter::Transparent, true, ctx.view.cameraPosition);
        });
  }

  // The view depth_peeling.remaining: the tail's fragments counted per pixel (additive blend).
  void addRemainingView(FrameGraph& frame, const std::string& last, bool counting) {
    const std::string view = aovResource(kRemainingView);
    frame.addPass("depth_peeling.view_remaining",
        [&](PassBuilder& b) {
          b.read(last);
          b.read(res::kDepth);
          b.write(view, frameTexture(frame, GL_RGBA32F));
          if (counting) b.readWriteBuffer(kCounts, BufferBinding::Storage, kCountsBinding);
        },
        [=, this](PassContext& ctx) {
          const std::vector<std::string> defines = takeCount(ctx, counting);
          const gl::Framebuffer& fbo = ctx.framebuffer("depth_peeling.view_remaining", {view});
          beginGeometry(ctx, fbo);
          const float start[4] = {0, 0, 0, 1}; // count 0, mask 1 everywhere
          glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, start);
          glEnable(GL_BLEND);
          glBlendFunc(GL_ONE, GL_ONE);
          gl::Program& p = peelProgram(ctx, defines);
          bindTailDepths(ctx, p, last, kRemaining);
          ctx.sceneGpu.draw(p, SceneGpu::Filter::Transparent, false);
        });
  }

  // depth_peeling.composite: colour output = Over of the layers onto the opaque colour (or the tail).
  void addComposite(FrameGraph& frame, bool tail, bool blend) {
    const std::string input = frame.colorInput(), output = frame.colorOutput();
    frame.addPass("depth_peeling.composite",
        [&](PassBuilder& b) {
          b.read(input);
          b.read(kAccum);
          if (tail) {
            b.read(kTailSum);
            b.read(kTailReveal);
          }
          b.write(output, frameTexture(frame, GL_RGBA16F));
          HdrClampCounters::declareUse(frame, b);
        },
        [=](PassContext& ctx) {
          std::vector<std::string> defines;
          if (blend) defines.push_back("TAIL_BLEND");
          if (ctx.common.hdrClamp.counting()) defines.push_back("HDR_CLAMP_COUNT");
          gl::Program& p =
              ctx.programs.get({{"common/fullscreen.vert", "depth_peeling/composite.frag"}, defines, "depth_peeling.composite"});
          ctx.beginFullscreen("depth_peeling.composite", {output});
          p.use();
          ctx.texture(input).bind(0);
          ctx.texture(kAccum).bind(1);
          p.set("uColor", 0).set("uAccum", 1);
          if (blend) {
            ctx.texture(kTailSum).bind(2);
            ctx.texture(kTailReveal).bind(3);
            p.set("uTailSum", 2).set("uTailReveal", 3);
          }
          ctx.common.hdrClamp.bind(p, "depth_peeling.composite");
          ctx.common.drawFullscreen();
        });
  }

  TechniqueInfo m_info = staticInfo();
  gl::BufferObject m_counts;
  bool m_countPending = false; // a counting frame whose count has not been taken yet
  bool m_countValid = false;   // the last frame counted
  bool m_blend = false;
};

} // namespace depth_peeling

void registerTechnique_depth_peeling(TechniqueRegistry& registry) {
  registerTechniqueType<depth_peeling::DepthPeeling>(registry);
}

} // namespace rtlab
