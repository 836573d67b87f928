// Shadow map — Williams 1978, "Casting curved shadows on curved surfaces".
// Approximates the visibility of light 0 by one depth comparison against the shadow stage's
// light-space depth map: binary, with the stage's constant, slope and normal-offset biases.
// It has no parameters of its own: resolution, format and biases are the shadow stage's
// (shadow.*), shared with every depth-comparison technique.
#include "frame/frame_graph.h"
#include "frame/registry.h"
#include "techniques/common/shadow/shadow_pass.h"

namespace rtlab {
namespace {

class ShadowMap final : public Technique {
public:
  static TechniqueInfo staticInfo() {
    TechniqueInfo info;
    info.id = "shadow_map";
    info.stage = "shadow";
    info.title = "Shadow map (Williams 1978)";
    info.summary = "Binary visibility of light 0 from one depth comparison against the light-space depth map";
    info.debugViews = {lightDepthView("shadow_map")};
    return info;
  }
  const TechniqueInfo& info() const override { return m_info; }

  void setup(FrameGraph& frame) override {
    ShadowScreenPass pass;
    pass.name = "shadow_map.visibility";
    pass.output = "visibility";
    pass.fragment = "shadow_map/visibility.frag";
    addShadowScreenPass(frame, pass);
    addLightDepthView(frame, "shadow_map.light_depth", m_kit);
  }
  std::size_t ownedBytes() const override { return m_kit.ownedBytes(); }

private:
  TechniqueInfo m_info = staticInfo();
  ShadowFilterKit m_kit;
};

} // namespace

void registerTechnique_shadow_map(TechniqueRegistry& registry) { registerTechniqueType<ShadowMap>(registry); }

} // namespace rtlab
