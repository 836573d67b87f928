// rsm — Dachsbacher and Stamminger 2005, "Reflective Shadow Maps" (I3D). Approximates the indirect
// stage's one bounce of diffuse light (docs/measuring.md "indirect") by treating every texel of
// light 0's light-space G-buffer (techniques/common/rsm/rsm_gbuffer.h) as a Lambertian virtual
// point light and summing the irradiance of the VPLs sampled around the pixel's projection in the
// map, without visibility. Computed at rsm.indirect_scale of the frame and upsampled depth- and
// normal-aware. techniques/rsm/README.md has the estimator, its normalisation and the guards.
#include "frame/frame_graph.h"
#include "frame/registry.h"
#include "gl/program_cache.h"
#include "params/param_set.h"
#include "shading/base_passes.h"
#include "shading/gpu_common.h"
#include "techniques/common/rsm/rsm_gbuffer.h"

#include <algorithm>
#include <cmath>

namespace rtlab {
namespace {

const std::string kRaw = "rsm.raw"; // reduced resolution: rgb irradiance, a contributing VPLs
// Texels one all_texels draw examines per pixel at most: llvmpipe ends a loop nest after 65535
// iterations per invocation (measured: a 259 x 259 loop lost its last rows, a 515 x 515 one gave 0).
constexpr int kMaxLoopIterations = 60000;

struct Layout {
  int scale = 2; // frame pixels per indirect texel along each axis
  int width = 0, height = 0;
};

Layout layoutOf(const FrameGraph& frame) {
  static const int kScales[3] = {4, 2, 1}; // rsm.indirect_scale 1/4, 1/2, 1
  Layout l;
  l.scale = kScales[frame.params().getEnum("rsm.indirect_scale")];
  l.width = (frame.width() + l.scale - 1) / l.scale;
  l.height = (frame.height() + l.scale - 1) / l.scale;
  return l;
}

class Rsm final : public Technique {
public:
  static TechniqueInfo staticInfo() {
    TechniqueInfo info;
    info.id = "rsm";
    info.stage = "indirect";
    info.title = "Reflective shadow maps (Dachsbacher and Stamminger 2005)";
    info.summary = "Irradiance of the light-space G-buffer's texels as Lambertian VPLs, sampled within rsm.r_max of "
                   "the pixel's projection (no visibility)";
    info.showcaseScene = "cornell";
    info.params = {
        ParamSpec::integer("rsm.samples", "Samples", 400, 16, 1024)
            .logScale()
            .withUnit("VPLs")
            .withHelp("VPLs sampled per pixel within rsm.r_max of its projection (rsm.sampling pattern)"),
        ParamSpec::real("rsm.r_max", "Sampling radius", 0.1, 0.01, 0.5)
            .withUnit("map uv")
            .withHelp("Radius of the disc around the pixel's projection in the light-space map, in uv units of "
                      "a face (1 = the face's width)"),
        ParamSpec::integer("rsm.weight_exponent", "Weight exponent", 2, 1, 2)
            .withHelp("Sample weight xi1^k for the pattern's radius xi1: 2 as published (over-weights the rim), "
                      "1 is the disc's area density (unbiased against rsm.sampling=all_texels)"),
        ParamSpec::choice("rsm.sampling", "Sampling", {"pattern", "all_texels"}, 0)
            .withFlags(kParamRecompile)
            .withHelp("pattern: rsm.samples polar samples (the paper's); all_texels: every texel whose centre lies "
                      "within rsm.r_max (the reference of the sampling error; slow)"),
        ParamSpec::integer("rsm.resolution", "RSM resolution", 512, 64, 1024)
            .logScale()
            .withUnit("texels")
            .withFlags(kParamRealloc)
            .withHelp("Side of each light-space map (flux, normal, position); six faces for a point light"),
        ParamSpec::choice("rsm.indirect_scale", "Indirect scale", {"1/4", "1/2", "1"}, 1)
            .withFlags(kParamRealloc)
            .withHelp("Resolution of the indirect pass relative to the frame; upsampled depth- and normal-aware"),
        ParamSpec::real("rsm.intensity", "Intensity", 1.0, 0.0, 4.0)
            .withHelp("Multiplier of the indirect irradiance (1 = physically based)"),
        ParamSpec::real("rsm.distance_clamp", "Distance clamp", 1.0, 0.0, 2.0)
            .withUnit("texel footprints")
            .withHelp("Lower bound of |x - x_p| in the VPL term, in world sizes of the VPL's texel (guards the "
                      "1/|x - x_p|^4 spike in corners; 0 = none)"),
    };
    info.debugViews = {
        {"rsm.flux", 3,
         "the light-space flux map as reflected radiance Phi_p / (pi A_perp) (a cube map as a 3 x 2 atlas: +X -X +Y "
         "over -Y +Z -Z)"},
        {"rsm.vpl_count", 1,
         "VPLs in front of both normals (that contributed) per pixel, divided by rsm.samples (pattern) or by the "
         "texels in the disc (all_texels)"},
    };
    return info;
  }

  const TechniqueInfo& info() const override { return m_info; }

  void setup(FrameGraph& frame) override {
    const int resolution = frame.params().getInt("rsm.resolution");
    const Layout l = layoutOf(frame);
    addRsmGBufferPass(frame, resolution);
    addEstimator(frame, l);
    addUpsample(frame, l, "rsm.upsample", "indirect", false);
    addUpsample(frame, l, "rsm.view_vpl_count", aovResource("rsm.vpl_count"), true);
    addRsmFluxView(frame, resolution, "rsm.flux");
  }

private:
  static void addEstimator(FrameGraph& frame, const Layout& l) {
    std::vector<std::string> defines;
    const bool all = frame.params().getEnumName("rsm.sampling") == "all_texels";
    if (all) defines.push_back("ALL_TEXELS");
    gl::TextureDesc raw;
    raw.format = GL_RGBA32F;
    raw.width = l.width;
    raw.height = l.height;
    frame.addPass(
        "rsm.indirect",
        [&](PassBuilder& b) {
          b.read(kRsmFlux);
          b.read(kRsmNormal);
          b.read(kRsmPosition);
          b.read(res::kPosition);
          b.read(res::kNormal);
          b.write(kRaw, raw);
        },
        [defines, l, all](PassContext& ctx) {
          gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "rsm/indirect.frag"}, defines, "rsm.indirect"});
          ctx.beginFullscreen("rsm.indirect", {kRaw});
          p.use();
          bindRsm(ctx, p, 0);
          ctx.texture(res::kPosition).bind(3);
          ctx.texture(res::kNormal).bind(4);
          p.set("uPosition", 3)
              .set("uNormal", 4)
              .set("uScale", l.scale)
              .set("uFullSize", glm::ivec2(ctx.view.width, ctx.view.height))
              .set("uSamples", ctx.params.getInt("rsm.samples"))
              .set("uRMax", ctx.params.getFloat("rsm.r_max"))
              .set("uWeightExponent", ctx.params.getInt("rsm.weight_exponent"))
              .set("uDistanceClamp", ctx.params.getFloat("rsm.distance_clamp"))
              .set("uIntensity", ctx.params.getFloat("rsm.intensity"));
          if (!all) {
            ctx.common.drawFullscreen();
            return;
          }
          // The all-texel sum in bands of rows, added up by blending (shaders/rsm/indirect.frag).
          const int reach = int(std::ceil(ctx.params.getFloat("rsm.r_max") * float(rsmResolution(ctx)))) + 1;
          const int rowsPerDraw = std::max(1, kMaxLoopIterations / (2 * reach + 1));
          glEnable(GL_BLEND);
          glBlendFunc(GL_ONE, GL_ONE);
          glBlendEquation(GL_FUNC_ADD);
          const float zero[4] = {0, 0, 0, 0};
          glClearBufferfv(GL_COLOR, 0, zero);
          p.set("uReach", reach);
          for (int row = -reach; row <= reach; row += rowsPerDraw) {
            p.set("uRowBegin", row).set("uRowEnd", row + rowsPerDraw - 1);
            ctx.common.drawFullscreen();
          }
        });
  }

  // rsm.raw to frame resolution: the stage output `indirect` (RGBA16F) or, with `count`, the
  // rsm.vpl_count view (RGBA32F with mask).
  static void addUpsample(FrameGraph& frame, const Layout& l, const std::string& name, const std::string& output,
                          bool count) {
    std::vector<std::string> defines;
    if (count) defines.push_back("OUTPUT_COUNT");
    const float sigma = 0.01f * frame.scene().worldBounds().radius();
    frame.addPass(
        name,
        [&](PassBuilder& b) {
          b.read(kRaw);
          b.read(res::kPosition);
          b.read(res::kNormal);
          b.write(output, frameTexture(frame, count ? GL_RGBA32F : GL_RGBA16F));
        },
        [=](PassContext& ctx) {
          gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "rsm/upsample.frag"}, defines, "rsm.upsample"});
          ctx.beginFullscreen(name, {output});
          p.use();
          ctx.texture(kRaw).bind(0);
          ctx.texture(res::kPosition).bind(1);
          ctx.texture(res::kNormal).bind(2);
          p.set("uRaw", 0)
              .set("uPosition", 1)
              .set("uNormal", 2)
              .set("uScale", l.scale)
              .set("uRawSize", glm::ivec2(l.width, l.height))
              .set("uFullSize", glm::ivec2(ctx.view.width, ctx.view.height))
              .set("uPlaneSigma", sigma);
          ctx.common.drawFullscreen();
        });
  }

  TechniqueInfo m_info = staticInfo();
};

} // namespace

void registerTechnique_rsm(TechniqueRegistry& registry) {
  registerTechniqueType<Rsm>(registry);
}

} // namespace rtlab
