// PCSS — Fernando 2005, "Percentage-closer soft shadows" (NVIDIA / SIGGRAPH sketch).
// Approximates the visibility of light 0 as an area light: a blocker search estimates the mean
// occluder depth, similar triangles give the penumbra width from the light's size (light0.radius
// for spot/point lights, light0.angle for directional lights), and PCF filters with that width —
// so shadows harden towards contacts.
#include "frame/frame_graph.h"
#include "frame/registry.h"
#include "params/param_set.h"
#include "techniques/common/shadow/shadow_pass.h"


namespace rtlab {
namespace {

class Pcss final : public Technique {
public:
  static TechniqueInfo staticInfo() {
    TechniqueInfo info;
    info.id = "pcss";
    info.stage = "shadow";
    info.title = "Percentage-closer soft shadows (Fernando 2005)";
    info.summary = "Blocker search, penumbra from similar triangles and the light's size, then PCF of that width";
    info.params = {
        ParamSpec::integer("pcss.blocker_samples", "Blocker samples", 16, 1, 64).logScale().withUnit("taps")
            .withHelp("Depth taps of the blocker search"),
        ParamSpec::integer("pcss.filter_samples", "Filter samples", 32, 1, 64).logScale().withUnit("taps")
            .withHelp("Depth comparisons of the filtering step"),
        ParamSpec::boolean("pcss.rotate", "Rotate per pixel", true)
            .withHelp("Rotate the Poisson taps per pixel by blue noise (noise instead of banding)"),
        ParamSpec::boolean("pcss.receiver_plane_bias", "Receiver-plane bias", true)
            .withHelp("Compare filter taps against the receiver's plane at the tap's offset"),
    };
    for (auto& spec : softShadowParams("pcss", 32.0, 64.0, 128.0)) info.params.push_back(spec);
    info.debugViews = softShadowDebugViews("pcss");
    info.debugViews.push_back(lightDepthView("pcss"));
    info.showcaseScene = "contact";
    return info;
  }
  const TechniqueInfo& info() const override { return m_info; }

  void setup(FrameGraph& frame) override {
    const ParamSet& params = frame.params();
    const auto filterTaps = ShadowFilterKit::taps(ShadowFilterKit::Pattern::Poisson, params.getInt("pcss.filter_samples"));
    const auto searchTaps = ShadowFilterKit::taps(ShadowFilterKit::Pattern::Poisson, params.getInt("pcss.blocker_samples"));
    auto bind = [this, filterTaps, searchTaps](PassContext& ctx, gl::Program& p) {
      m_kit.bindFilter(p, filterTaps, ctx.params.getBool("pcss.rotate"), ctx.params.getBool("pcss.receiver_plane_bias"), false);
      m_kit.bindRawDepth(ctx, p, "uShadowRaw", 4);
      p.set("uSearchTaps", searchTaps)
          .set("uSearchTapCount", int(searchTaps.size()));
      setSoftShadowUniforms(ctx, p, "pcss");
    };
    ShadowScreenPass pass;
    pass.fragment = "pcss/visibility.frag";
    pass.bind = bind;
    addSoftShadowPasses(frame, "pcss", pass);
    addLightDepthView(frame, "pcss.light_depth", m_kit);
  }
  std::size_t ownedBytes() const override { return m_kit.ownedBytes(); }

private:
  TechniqueInfo m_info = staticInfo();
  ShadowFilterKit m_kit;
};

} // namespace

void registerTechnique_pcss(TechniqueRegistry& registry) { registerTechniqueType<Pcss>(registry); }

} // namespace rtlab
