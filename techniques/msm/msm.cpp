// MSM — Peters & Klein 2015, "Moment shadow mapping" (Hamburger 4MSM), with soft shadows: four
// depth moments averaged over a box from a summed-area table, the box sized by a PCSS-style
// blocker estimate and the light's size. The 4-moment bound leaks much less light than VSSM's
// 2-moment Chebyshev bound where occluders overlap at several depths.
#include "frame/frame_graph.h"
#include "frame/registry.h"
#include "params/param_set.h"
#include "techniques/common/shadow/moment_map.h"
#include "techniques/common/shadow/shadow_pass.h"

namespace rtlab {
namespace {

class Msm final : public Technique {
public:
  static TechniqueInfo staticInfo() {
    TechniqueInfo info;
    info.id = "msm";
    info.stage = "shadow";
    info.title = "Moment shadow mapping (Peters & Klein 2015)";
    info.summary = "Hamburger 4-moment bound over a box from a summed-area table, sized by a blocker estimate";
    info.params = {
        ParamSpec::choice("msm.format", "Moment format", {"rgba32f", "rgba16_optimized", "rgba16f_optimized"}, 1)
            .withFlags(kParamRealloc | kParamRecompile)
            .withHelp("Storage of the moments, always in the paper's optimized basis: 32-bit float, 16-bit normalized "
                      "integers (the paper's 64-bit MSM), or 16-bit half floats (too coarse: speckles)"),
        ParamSpec::real("msm.moment_bias", "Moment bias", 3e-5, 1e-7, 1e-1).logScale()
            .withHelp("Moments are pulled towards those of a uniform depth distribution by this much (alpha), keeping the Hankel matrix invertible"),
        ParamSpec::boolean("msm.sat_offset", "Offset before summing", true)
            .withHelp("Subtract 0.5 from the moments before building the fixed-point summed-area table (halves its sums: one more bit)"),
        ParamSpec::real("msm.bleed_reduction", "Light-bleeding reduction", 0.1, 0.0, 0.95)
            .withHelp("Visibility below this is cut to 0 and the rest rescaled, as vssm.bleed_reduction (less bleeding, harder edges; 0: the raw 4MSM bound)"),
        ParamSpec::choice("msm.blocker_search", "Blocker search", {"two_moment", "four_moment"}, 0)
            .withFlags(kParamRecompile)
            .withHelp("Mean blocker depth from the first two moments (Yang et al. 2010, as VSSM) or from all four (Peters et al. 2016)"),
    };
    info.params.push_back(momentSatBitsParam("msm"));
    info.params.push_back(ParamSpec::boolean("msm.centred", "Moments about the receiver", true)
        .withHelp("Shift the box's moments to the receiver's depth in double before the 4MSM bound (the same bound; float "
                  "no longer cancels on boxes of one depth: README, \"Precision\")"));
    for (auto& spec : softShadowParams("msm", 64.0, 256.0, 256.0)) info.params.push_back(spec);
    info.debugViews = softShadowDebugViews("msm");
    info.debugViews.push_back({"msm.moments", 1, "first channel of the moment map as stored (the optimized transform of z^1..z^4)"});
    return info;
  }
  const TechniqueInfo& info() const override { return m_info; }

  void setup(FrameGraph& frame) override {
    const std::string& format = frame.params().getEnumName("msm.format");
    MomentMapConfig config;
    config.technique = "msm";
    config.moments = 4;
    config.format = format == "rgba16_optimized" ? GL_RGBA16 : format == "rgba16f_optimized" ? GL_RGBA16F : GL_RGBA32F;
    // Every format stores, and the table sums, the moments in the optimized basis: its
    // fixed-point rounding then disturbs the 4MSM bound as little as the paper's 16-bit
    // quantization does (README, "Speckles").
    config.optimized = true;
    config.satOffset = frame.params().getBool("msm.sat_offset");
    addMomentMapPasses(frame, config);
    ShadowScreenPass pass;
    pass.fragment = "msm/visibility.frag";
    pass.depthMap = false;
    pass.reads = {momentSatResource("msm")};
    pass.defines.push_back("OPTIMIZED");
    if (frame.params().getEnumName("msm.blocker_search") == "four_moment") pass.defines.push_back("FOUR_MOMENT_SEARCH");
    pass.bind = [config](PassContext& ctx, gl::Program& p) {
      bindMomentSat(ctx, p, config, 3);
      p.set("uMomentBias", ctx.params.getFloat("msm.moment_bias"))
          .set("uBleedReduction", ctx.params.getFloat("msm.bleed_reduction"))
          .set("uCentred", ctx.params.getBool("msm.centred"));
      setSoftShadowUniforms(ctx, p, "msm");
    };
    addSoftShadowPasses(frame, "msm", pass);
    addMomentView(frame, "msm", "msm.moments");
  }

private:
  TechniqueInfo m_info = staticInfo();
};

} // namespace

void registerTechnique_msm(TechniqueRegistry& registry) { registerTechniqueType<Msm>(registry); }

} // namespace rtlab
