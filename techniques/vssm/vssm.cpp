// VSSM — Yang, Dong, Feng, Seidel & Kautz 2010, "Variance soft shadow mapping" (CGF 29(7)), on
// variance shadow maps (Donnelly & Lauritzen 2006). Approximates the visibility of light 0 as an
// area light with PCSS's three steps, each done in constant time from a summed-area table of the
// depth moments (z, z^2): Chebyshev's bound replaces the per-texel depth comparisons.
#include "frame/frame_graph.h"
#include "frame/registry.h"
#include "params/param_set.h"
#include "techniques/common/shadow/moment_map.h"
#include "techniques/common/shadow/shadow_pass.h"

namespace rtlab {
namespace {

class Vssm final : public Technique {
public:
  static TechniqueInfo staticInfo() {
    TechniqueInfo info;
    info.id = "vssm";
    info.stage = "shadow";
    info.title = "Variance soft shadow mapping (Yang et al. 2010)";
    info.summary = "PCSS's blocker search and filtering in constant time from a summed-area table of (z, z^2)";
    info.params = {
        ParamSpec::choice("vssm.format", "Moment format", {"rg32f", "rg16f"}, 0).withFlags(kParamRealloc)
            .withHelp("Storage of the moment map (the summed-area table is always 32-bit fixed point)"),
        ParamSpec::boolean("vssm.sat_offset", "Offset before summing", true)
            .withHelp("Subtract 0.5 from the moments before building the fixed-point summed-area table (halves its sums: one more bit)"),
        ParamSpec::real("vssm.min_variance", "Minimum variance", 1e-5, 1e-8, 1e-2).logScale()
            .withHelp("Variance floor of Chebyshev's bound (against acne on planar receivers)"),
        ParamSpec::real("vssm.bleed_reduction", "Light-bleeding reduction", 0.2, 0.0, 0.95)
            .withHelp("Bound values below this are cut to 0 and the rest rescaled (less bleeding, harder edges)"),
    };
    info.params.push_back(momentSatBitsParam("vssm"));
    for (auto& spec : softShadowParams("vssm", 64.0, 256.0, 256.0)) info.params.push_back(spec);
    info.debugViews = softShadowDebugViews("vssm");
    info.debugViews.push_back({"vssm.moments", 1, "first moment: mean normalized linear light depth (0 near, 1 far)"});
    return info;
  }
  const TechniqueInfo& info() const override { return m_info; }

  void setup(FrameGraph& frame) override {
    MomentMapConfig config;
    config.technique = "vssm";
    config.moments = 2;
    config.format = frame.params().getEnumName("vssm.format") == "rg16f" ? GL_RG16F : GL_RG32F;
    config.satOffset = frame.params().getBool("vssm.sat_offset");
    addMomentMapPasses(frame, config);
    ShadowScreenPass pass;
    pass.fragment = "vssm/visibility.frag";
    pass.depthMap = false;
    pass.reads = {momentSatResource("vssm")};
    pass.bind = [config](PassContext& ctx, gl::Program& p) {
      bindMomentSat(ctx, p, config, 3);
      p.set("uMinVariance", ctx.params.getFloat("vssm.min_variance"))
          .set("uBleedReduction", ctx.params.getFloat("vssm.bleed_reduction"));
      setSoftShadowUniforms(ctx, p, "vssm");
    };
    addSoftShadowPasses(frame, "vssm", pass);
    addMomentView(frame, "vssm", "vssm.moments");
  }

private:
  TechniqueInfo m_info = staticInfo();
};

} // namespace

void registerTechnique_vssm(TechniqueRegistry& registry) { registerTechniqueType<Vssm>(registry); }

} // namespace rtlab
