// Shadow map — Williams 1978, "Casting curved shadows on curved surfaces".
// Approximates the visibility of light 0 by one depth comparison against the shadow stage's
// light-space depth map: binary, with the stage's constant, slope and normal-offset biases.
// It has no parameters of its own: resolution, format and biases are the shadow stage's
// (shadow.*), shared with every depth-comparison technique.
#include "frame/frame_graph.h"
#include "frame/registry.h"
#include "gl/program_cache.h"
#include "shading/base_passes.h"
#include "shading/gpu_common.h"
#include "shading/shadow_depth.h"

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
    info.debugViews = {{"shadow_map.light_depth", 1, "light-space depth of light 0, linear from its near (0) to far (1) plane (cube maps unwrapped)"}};
    return info;
  }
  const TechniqueInfo& info() const override { return m_info; }

  void setup(FrameGraph& frame) override {
    addShadowDepthPass(frame);
    const std::string projection = shadowProjectionDefine(shadowLightSpace(frame.scene(), frame.params()));
    frame.addPass("shadow_map.visibility",
        [&](PassBuilder& b) {
          b.read(kShadowDepth);
          b.read(res::kPosition);
          b.read(res::kGeometry);
          b.write("visibility", frameTexture(frame, GL_R16F));
        },
        [projection](PassContext& ctx) {
          gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "shadow_map/visibility.frag"}, {projection}, "shadow_map.visibility"});
          ctx.beginFullscreen("shadow_map.visibility", {"visibility"});
          p.use();
          ctx.texture(res::kPosition).bind(0);
          ctx.texture(res::kGeometry).bind(1);
          p.set("uPosition", 0).set("uGeometry", 1);
          bindShadowSpace(ctx, p, 2);
          ctx.common.drawFullscreen();
        });
    frame.addPass("shadow_map.light_depth",
        [&](PassBuilder& b) {
          b.read(kShadowDepth);
          b.write(aovResource("shadow_map.light_depth"), frameTexture(frame, GL_RGBA32F));
        },
        [this, projection](PassContext& ctx) {
          gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "shadow_map/light_depth.frag"}, {projection}, "shadow_map.light_depth"});
          const std::string out = aovResource("shadow_map.light_depth");
          ctx.beginFullscreen(out, {out});
          if (!m_rawDepth) {
            m_rawDepth = gl::Sampler("shadow_map.raw-depth");
            glSamplerParameteri(m_rawDepth.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
            glSamplerParameteri(m_rawDepth.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glSamplerParameteri(m_rawDepth.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            glSamplerParameteri(m_rawDepth.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glSamplerParameteri(m_rawDepth.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
          }
          p.use();
          ctx.texture(kShadowDepth).bind(0);
          glBindSampler(0, m_rawDepth.id());
          const LightSpace ls = shadowLightSpace(ctx.scene, ctx.params);
          p.set("uDepth", 0).set("uNear", ls.znear).set("uFar", ls.zfar);
          ctx.common.drawFullscreen();
        });
  }

private:
  TechniqueInfo m_info = staticInfo();
  gl::Sampler m_rawDepth;
};

} // namespace

void registerTechnique_shadow_map(TechniqueRegistry& registry) { registerTechniqueType<ShadowMap>(registry); }

} // namespace rtlab
