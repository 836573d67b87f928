// Weighted blended order-independent transparency — Morgan McGuire and Louis Bavoil, "Weighted
// Blended Order-Independent Transparency", JCGT 2(2), 2013 (docs/contract.md "Transparency").
// One pass over the transparent fragments in any order sums (α C w, α w) and multiplies
// Π(1 - α) with fixed-function blending; a full-screen pass divides the sums and composites the
// average over the opaque colour. Constant cost per fragment, no sorting, approximate: the depth
// weight w stands in for the order. techniques/wboit/README.md has the formulas, the numerical
// guards, the artifacts and the measured cost.
#include "frame/frame_graph.h"
#include "frame/registry.h"
#include "gl/program_cache.h"
#include "params/param_set.h"
#include "shading/base_passes.h"
#include "techniques/common/transparency/abuffer_error.h"
#include "shading/gpu_common.h"
#include "shading/hdr_clamp.h"
#include "shading/scene_gpu.h"

#include <cfloat>

namespace rtlab {
namespace {

constexpr const char* kAccum = "wboit.accum";
constexpr const char* kReveal = "wboit.reveal";
constexpr const char* kCount = "wboit.count";
constexpr const char* kCounts = "wboit.counts";
constexpr int kCountsBinding = 0; // shaders/wboit/accumulate.frag and composite.frag

// RGBA16F accumulation: the sums are stored times 1/16, and one fragment adds at most 65504/64 to
// a channel (README "Numerical guards"). RGBA32F needs neither.
constexpr float kHalfScale = 1.0f / 16.0f;
constexpr float kHalfFragmentCap = 65504.0f / 64.0f;

const std::vector<std::string> kWeights = {"eq7", "eq8", "eq9", "eq10", "color9"};

struct Formats {
  GLenum accum, reveal;
  float scale, fragmentCap, storageMax;
};

Formats formatsFrom(const ParamSet& params) {
  Formats f;
  const bool accum32 = params.getEnumName("wboit.accum_format") == "rgba32f";
  f.accum = accum32 ? GL_RGBA32F : GL_RGBA16F;
  f.reveal = params.getEnumName("wboit.reveal_format") == "r16f" ? GL_R16F : GL_R8;
  f.scale = accum32 ? 1.0f : kHalfScale;
  f.fragmentCap = accum32 ? FLT_MAX : kHalfFragmentCap;
  f.storageMax = accum32 ? FLT_MAX : 65504.0f;
  return f;
}

// The weight's uniforms (shaders/wboit/weight.glsl).
struct Weight {
  int function = 4;
  float depthScale = 200, exponent = 4, minWeight = 1e-2f, maxWeight = 3e3f;
};

Weight weightFrom(const ParamSet& params) {
  Weight w;
  w.function = params.getEnum("wboit.weight");
  w.depthScale = params.getFloat("wboit.depth_scale");
  w.exponent = params.getFloat("wboit.exponent");
  w.minWeight = params.getFloat("wboit.min_weight");
  w.maxWeight = params.getFloat("wboit.max_weight");
  return w;
}

class Wboit final : public Technique {
public:
  static TechniqueInfo staticInfo() {
    TechniqueInfo info;
    info.id = "wboit";
    info.stage = "transparency";
    info.title = "Weighted blended OIT (McGuire & Bavoil 2013)";
    info.summary = "One unsorted pass sums (a C w, a w) and prod(1 - a); the composite divides and blends the "
                   "weighted average over the opaque colour (approximate, constant cost)";
    info.showcaseScene = "layers";
    info.params = {
        ParamSpec::choice("wboit.weight", "Weight function", kWeights, 4)
            .withHelp("w = a f(z), the paper's equations: eq7 and eq8 (view depth, two terms), eq9 "
                      "(0.03/(1e-5 + (|z|/depth_scale)^exponent)), eq10 (window depth, 3e3 (1 - d)^3), "
                      "color9 (eq9 with a = max(min(1, max(C) a), a))"),
        ParamSpec::real("wboit.depth_scale", "Depth scale", 200.0, 10.0, 1000.0)
            .logScale().withUnit("scene units")
            .withHelp("eq9 and color9: s of 0.03/(1e-5 + (|z|/s)^exponent): the factor is 3e3 near the camera, "
                      "half that at |z| = s 1e-5^(1/exponent) (0.056 s for exponent 4), 0.03 at |z| = s"),
        ParamSpec::real("wboit.exponent", "Exponent", 4.0, 1.0, 8.0)
            .withHelp("eq9 and color9: how steeply the weight falls with view depth"),
        ParamSpec::real("wboit.min_weight", "Minimum weight", 1e-2, 1e-3, 1e-1)
            .logScale().withHelp("Lower clamp of the depth factor f, every equation (the paper's 1e-2)"),
        ParamSpec::real("wboit.max_weight", "Maximum weight", 3e3, 1e2, 3e3)
            .logScale().withHelp("Upper clamp of the depth factor f, every equation (the paper's 3e3)"),
        ParamSpec::choice("wboit.accum_format", "Accumulation format", {"rgba16f", "rgba32f"}, 0)
            .withFlags(kParamRealloc)
            .withHelp("Format of the sums (a C w, a w); rgba16f stores them times 1/16 and caps each fragment's "
                      "share (techniques/wboit/README.md)"),
        ParamSpec::choice("wboit.reveal_format", "Revealage format", {"r8", "r16f"}, 0)
            .withFlags(kParamRealloc)
            .withHelp("Format of prod(1 - a): r8 rounds 1 - a back to 1 for a < 1/510 (small a lost)"),
    };
    info.debugViews = {
        {"wboit.revealage", 1, "revealage prod(1 - a) over the pixel's transparent fragments (1: uncovered)"},
        {"wboit.weight", 1, "accumulated weight sum(a w), the divisor of the average before its clamp"},
        {"wboit.complexity", 1, "transparent fragments per pixel in front of the opaque depth"},
        {AbufferError::viewName("wboit"), 1, AbufferError::viewHelp()},
    };
    return info;
  }
  const TechniqueInfo& info() const override { return m_info; }

  void setup(FrameGraph& frame) override {
    const ParamSet& params = frame.params();
    const Formats formats = formatsFrom(params);
    const bool counting = frame.isImported(HdrClampCounters::kResource);
    if (counting) {
      if (!m_counts) m_counts = gl::BufferObject({gl::BufferKind::Storage, 2 * sizeof(GLuint)}, kCounts);
      frame.importBuffer(kCounts, m_counts);
      m_counted = true;
    }
    addAccumulation(frame, formats, weightFrom(params), counting);
    addComposite(frame, formats, counting);
    addCount(frame);
    addView(frame, "wboit.view_revealage", "wboit.revealage", kReveal, "VIEW_REVEALAGE", 1.0f);
    addView(frame, "wboit.view_weight", "wboit.weight", kAccum, "VIEW_WEIGHT", 1.0f / formats.scale);
    addView(frame, "wboit.view_complexity", "wboit.complexity", kCount, "VIEW_COMPLEXITY", 1.0f);
    m_error.add(frame, "wboit", frame.colorOutput());
  }

  // A new scene's geometry: the error view's A-buffer pool (sized for the old one) goes.
  void sceneChanged(const SceneChange& change) override {
    if (change.geometry) m_error.release();
  }

  std::size_t ownedBytes() const override { return (m_counts ? 2 * sizeof(GLuint) : 0) + m_error.ownedBytes(); }

  std::vector<TechniqueCounter> counters() const override {
    std::vector<TechniqueCounter> out;
    if (m_counted && m_counts) {
      glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
      const std::vector<GLuint> v = m_counts.downloadAs<GLuint>();
      out.push_back({"capped_fragments", double(v[0])});
      out.push_back({"overflowed_pixels", double(v[1])});
    }
    return out;
  }

private:
  AbufferError m_error; // the debug view <id>.error
  // Transparent fragments in front of the opaque depth -> wboit.accum (cleared to 0, blend ONE,
  // ONE) and wboit.reveal (cleared to 1, blend ZERO, ONE_MINUS_SRC_COLOR: dst * (1 - α)). The
  // depth buffer is tested, never written, so the layers do not hide each other; the scene's
  // back-to-front draw order is irrelevant to the sums (the tests shuffle it).
  void addAccumulation(FrameGraph& frame, const Formats& formats, const Weight& weight, bool counting) {
    frame.addPass("wboit.accumulate",
        [&](PassBuilder& b) {
          b.read(res::kDepth);
          b.write(kAccum, frameTexture(frame, formats.accum));
          b.write(kReveal, frameTexture(frame, formats.reveal));
          if (counting) b.readWriteBuffer(kCounts, BufferBinding::Storage, kCountsBinding);
          HdrClampCounters::declareUse(frame, b);
        },
        [=](PassContext& ctx) {
          std::vector<std::string> defines;
          if (counting) {
            defines.push_back("WBOIT_COUNT");
            ctx.buffer(kCounts).clear();
          }
          if (ctx.common.hdrClamp.counting()) defines.push_back("HDR_CLAMP_COUNT");
          const gl::Framebuffer& fbo = ctx.framebuffer("wboit.accumulate", {kAccum, kReveal}, res::kDepth);
          glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
          glViewport(0, 0, ctx.view.width, ctx.view.height);
          const float zero[4] = {0, 0, 0, 0}, one[4] = {1, 1, 1, 1};
          glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, zero);
          glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 1, one);
          glEnable(GL_DEPTH_TEST);
          glDepthFunc(GL_LESS);
          glDepthMask(GL_FALSE);
          glDisable(GL_CULL_FACE);
          glEnable(GL_BLEND);
          glBlendFunci(0, GL_ONE, GL_ONE);
          glBlendFunci(1, GL_ZERO, GL_ONE_MINUS_SRC_COLOR);
          gl::Program& p =
              ctx.programs.get({{"shading/surface.vert", "wboit/accumulate.frag"}, defines, "wboit.accumulate"});
          p.use();
          setLayerUniforms(p, ctx);
          p.set("uView", ctx.view.view)
              .set("uWeightFunction", weight.function)
              .set("uDepthScale", weight.depthScale)
              .set("uExponent", weight.exponent)
              .set("uMinWeight", weight.minWeight)
              .set("uMaxWeight", weight.maxWeight)
              .set("uAccumScale", formats.scale)
              .set("uFragmentCap", formats.fragmentCap);
          ctx.common.hdrClamp.bind(p, "wboit.accumulate");
          ctx.sceneGpu.draw(p, SceneGpu::Filter::Transparent, true, ctx.view.cameraPosition);
        });
  }

  void addComposite(FrameGraph& frame, const Formats& formats, bool counting) {
    const std::string input = frame.colorInput(), output = frame.colorOutput();
    frame.addPass("wboit.composite",
        [&](PassBuilder& b) {
          b.read(input);
          b.read(kAccum);
          b.read(kReveal);
          b.write(output, frameTexture(frame, GL_RGBA16F));
          if (counting) b.readWriteBuffer(kCounts, BufferBinding::Storage, kCountsBinding);
          HdrClampCounters::declareUse(frame, b);
        },
        [=](PassContext& ctx) {
          std::vector<std::string> defines;
          if (counting) defines.push_back("WBOIT_COUNT");
          if (ctx.common.hdrClamp.counting()) defines.push_back("HDR_CLAMP_COUNT");
          gl::Program& p =
              ctx.programs.get({{"common/fullscreen.vert", "wboit/composite.frag"}, defines, "wboit.composite"});
          ctx.beginFullscreen("wboit.composite", {output});
          p.use();
          ctx.texture(input).bind(0);
          ctx.texture(kAccum).bind(1);
          ctx.texture(kReveal).bind(2);
          p.set("uColor", 0)
              .set("uAccum", 1)
              .set("uReveal", 2)
              .set("uAccumScale", formats.scale)
              .set("uStorageMax", formats.storageMax);
          ctx.common.hdrClamp.bind(p, "wboit.composite");
          ctx.common.drawFullscreen();
        });
  }

  // Depth complexity for the view wboit.complexity: the same fragments as the accumulation, each
  // adding 1 to an R32F target. A pass of its own, so the graph culls it unless the view is asked for.
  void addCount(FrameGraph& frame) {
    frame.addPass("wboit.count",
        [&](PassBuilder& b) {
          b.read(res::kDepth);
          b.write(kCount, frameTexture(frame, GL_R32F));
        },
        [](PassContext& ctx) {
          const gl::Framebuffer& fbo = ctx.framebuffer("wboit.count", {kCount}, res::kDepth);
          glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
          glViewport(0, 0, ctx.view.width, ctx.view.height);
          const float zero[4] = {0, 0, 0, 0};
          glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, zero);
          glEnable(GL_DEPTH_TEST);
          glDepthFunc(GL_LESS);
          glDepthMask(GL_FALSE);
          glDisable(GL_CULL_FACE);
          glEnable(GL_BLEND);
          glBlendFunc(GL_ONE, GL_ONE);
          gl::Program& p = ctx.programs.get({{"shading/surface.vert", "wboit/count.frag"}, {}, "wboit.count"});
          p.use();
          p.set("uViewProj", ctx.view.viewProj);
          ctx.sceneGpu.draw(p, SceneGpu::Filter::Transparent, false, ctx.view.cameraPosition);
        });
  }

  void addView(FrameGraph& frame, const std::string& pass, const std::string& view, const std::string& source,
               const std::string& define, float scale) {
    const std::string out = aovResource(view);
    frame.addPass(pass,
        [&](PassBuilder& b) {
          b.read(source);
          b.write(out, frameTexture(frame, GL_RGBA32F));
        },
        [=](PassContext& ctx) {
          gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "wboit/view.frag"}, {define}, pass});
          ctx.beginFullscreen(out, {out});
          p.use();
          ctx.texture(source).bind(0);
          p.set("uSource", 0).set("uScale", scale);
          ctx.common.drawFullscreen();
        });
  }

  TechniqueInfo m_info = staticInfo();
  gl::BufferObject m_counts;
  bool m_counted = false;
};

} // namespace

void registerTechnique_wboit(TechniqueRegistry& registry) { registerTechniqueType<Wboit>(registry); }

} // namespace rtlab
