// PCF — Reeves, Salesin & Cook 1987, "Rendering antialiased shadows with depth maps".
// Approximates the visibility of light 0 by the fraction of depth comparisons that pass over a
// kernel around the receiver in the shadow stage's map: antialiased, uniformly soft edges (the
// kernel does not depend on the light's size; PCSS does).
#include "frame/frame_graph.h"
#include "frame/registry.h"
#include "params/param_set.h"
#include "techniques/common/shadow/shadow_pass.h"

namespace rtlab {
namespace {

class Pcf final : public Technique {
public:
  static TechniqueInfo staticInfo() {
    TechniqueInfo info;
    info.id = "pcf";
    info.stage = "shadow";
    info.title = "Percentage-closer filtering (Reeves et al. 1987)";
    info.summary = "Fraction of passing depth comparisons over a fixed kernel around the receiver";
    info.params = {
        ParamSpec::real("pcf.radius", "Kernel radius", 1.5, 0.0, 32.0).withUnit("texels")
            .withHelp("Radius of the tap kernel in shadow-map texels; 0 with hardware_2x2 off equals shadow_map"),
        ParamSpec::integer("pcf.samples", "Samples", 16, 1, 64).logScale().withUnit("taps")
            .withHelp("Depth comparisons per pixel (the grid pattern uses the largest square not above it)"),
        ParamSpec::choice("pcf.pattern", "Pattern", {"grid", "poisson", "poisson_rotated"}, 2)
            .withHelp("Tap layout: regular grid, Poisson disk, or Poisson disk rotated per pixel by blue noise"),
        ParamSpec::boolean("pcf.hardware_2x2", "Hardware 2x2", false)
            .withHelp("Bilinear depth comparison per tap (each tap is itself a 2x2 PCF)"),
        ParamSpec::boolean("pcf.receiver_plane_bias", "Receiver-plane bias", true)
            .withHelp("Compare each tap against the receiver's plane at the tap's offset (removes wide-kernel acne on slopes)"),
    };
    info.debugViews = {lightDepthView("pcf")};
    return info;
  }
  const TechniqueInfo& info() const override { return m_info; }

  void setup(FrameGraph& frame) override {
    const auto pattern = ShadowFilterKit::Pattern(frame.params().getEnum("pcf.pattern"));
    const auto taps = ShadowFilterKit::taps(pattern, frame.params().getInt("pcf.samples"));
    ShadowScreenPass pass;
    pass.name = "pcf.visibility";
    pass.output = "visibility";
    pass.fragment = "pcf/visibility.frag";
    pass.bind = [this, taps, pattern](PassContext& ctx, gl::Program& p) {
      m_kit.bindFilter(p, taps, pattern == ShadowFilterKit::Pattern::PoissonRotated,
                       ctx.params.getBool("pcf.receiver_plane_bias"), ctx.params.getBool("pcf.hardware_2x2"));
      p.set("uRadius", ctx.params.getFloat("pcf.radius"));
    };
    addShadowScreenPass(frame, pass);
    addLightDepthView(frame, "pcf.light_depth", m_kit);
  }
  std::size_t ownedBytes() const override { return m_kit.ownedBytes(); }

private:
  TechniqueInfo m_info = staticInfo();
  ShadowFilterKit m_kit;
};

} // namespace

void registerTechnique_pcf(TechniqueRegistry& registry) { registerTechniqueType<Pcf>(registry); }

} // namespace rtlab
