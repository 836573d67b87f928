// HBAO — Bavoil, Sainz & Dimitrov 2008, "Image-space horizon-based ambient occlusion"
// (SIGGRAPH 2008 talk; ShaderX7 chapter 6.2). Approximates the ao stage's output, the
// cosine-weighted unoccluded fraction within ao.radius, from the G-buffer alone: around each
// pixel it marches a few screen-space directions, finds in each the highest horizon among the
// surface points within ao.radius, and integrates the open part of the hemisphere above those
// horizons. The default integral weights directions by the cosine (the reference's quantity);
// Bavoil's solid-angle integral with per-sample attenuation is an option.
#include "frame/frame_graph.h"
#include "frame/registry.h"
#include "gl/program_cache.h"
#include "params/param_set.h"
#include "shading/base_passes.h"
#include "shading/gpu_common.h"

#include <glm/gtc/constants.hpp>

#include <string>
#include <vector>

namespace rtlab {
namespace {

constexpr int kProbeSpacing = 48; // pixels between the pattern view's probes

class Hbao final : public Technique {
public:
  static TechniqueInfo staticInfo() {
    TechniqueInfo info;
    info.id = "hbao";
    info.stage = "ao";
    info.title = "Horizon-based ambient occlusion (Bavoil, Sainz & Dimitrov 2008)";
    info.summary =
        "Horizons marched along screen-space directions bound the open part of the hemisphere within ao.radius";
    info.params = {
        ParamSpec::integer("hbao.directions", "Directions", 8, 1, 32)
            .logScale()
            .withUnit("directions")
            .withHelp("Screen-space directions marched per pixel (evenly spaced, rotated per pixel with hbao.jitter)"),
        ParamSpec::integer("hbao.steps", "Steps", 6, 1, 32)
            .logScale()
            .withUnit("taps")
            .withHelp("Depth taps per direction, spread from 1 pixel out to ao.radius projected into pixels"),
        ParamSpec::real("hbao.max_radius_px", "Max pixel radius", 128.0, 4.0, 1024.0)
            .logScale()
            .withUnit("pixels")
            .withHelp("Cap on ao.radius projected into pixels (near the camera it bounds the cost and the reach)"),
        ParamSpec::real("hbao.angle_bias", "Angle bias", 10.0, 0.0, 60.0)
            .withUnit("degrees")
            .withHelp("A tap occludes only if it rises this far above the tangent plane (hides tessellation)"),
        ParamSpec::real("hbao.attenuation", "Distance attenuation", 0.0, 0.0, 1.0)
            .withHelp(
                "Occluder weight 1 - a r^2/R^2 at distance r (Bavoil's falloff at 1; 0 keeps the hard ao.radius cut)"),
        ParamSpec::boolean("hbao.jitter", "Per-pixel jitter", true)
            .withHelp("Rotate the directions and offset the taps per pixel (noise, blurred away, instead of banding)"),
        ParamSpec::choice("hbao.integral", "Integral", {"cosine", "solid_angle"}, 0)
            .withFlags(kParamRecompile)
            .withHelp(
                "cosine: cosine-weighted horizon integral (the reference's ao); solid_angle: Bavoil's sin h - sin t"),
    };
    info.debugViews = {
        {"hbao.raw", 1, "HBAO before blur and upsampling (0 on background)"},
        {"hbao.pattern", 3,
         "taps of probe pixels over the dimmed raw AO: red raised the horizon, green within ao.radius below it, blue "
         "skipped (off-screen, background, beyond ao.radius); probes white"},
    };
    info.showcaseScene = "cornell";
    return info;
  }
  const TechniqueInfo& info() const override { return m_info; }

  void setup(FrameGraph& frame) override {
    const std::vector<std::string> defines = {"HBAO_INTEGRAL " +
                                              std::string(frame.params().getEnum("hbao.integral") == 0 ? "1" : "0")};
    addMarchPass(frame, "hbao.ao", "ao", "hbao/ao.frag", GL_R16F, defines);
    addMarchPass(frame, "hbao.raw", aovResource("hbao.raw"), "hbao/ao.frag", GL_R32F, defines);
    addMarchPass(frame, "hbao.pattern", aovResource("hbao.pattern"), "hbao/pattern.frag", GL_RGBA32F, defines);
  }

private:
  static void addMarchPass(FrameGraph& frame, const std::string& name, const std::string& output,
                           const std::string& fragment, GLenum format, const std::vector<std::string>& defines) {
    frame.addPass(
        name,
        [&](PassBuilder& b) {
          b.read(res::kPosition);
          b.read(res::kNormal);
          b.read(res::kGeometry);
          b.write(output, frameTexture(frame, format));
        },
        [=](PassContext& ctx) {
          gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", fragment}, defines, name});
          ctx.beginFullscreen(name, {output});
          p.use();
          ctx.texture(res::kPosition).bind(0);
          ctx.texture(res::kNormal).bind(1);
          ctx.texture(res::kGeometry).bind(2);
          p.set("uPosition", 0).set("uNormal", 1).set("uGeometry", 2);
          setMarchUniforms(ctx, p, 1);
          p.set("uProbeSpacing", kProbeSpacing);
          ctx.common.drawFullscreen();
        });
  }

  static void setMarchUniforms(PassContext& ctx, gl::Program& p, int gbufferStep) {
    const FrameView& view = ctx.view;
    const glm::mat4& v = view.view;
    p.set("uGbufferSize", glm::ivec2(view.width, view.height))
        .set("uGbufferStep", gbufferStep)
        .set("uCameraPosition", view.cameraPosition)
        .set("uCameraRight", glm::vec3(v[0][0], v[1][0], v[2][0]))
        .set("uCameraUp", glm::vec3(v[0][1], v[1][1], v[2][1]))
        .set("uCameraForward", view.cameraForward)
        .set("uFocalPx", view.proj[1][1] * 0.5f * float(view.height))
        .set("uRadius", ctx.params.getFloat("ao.radius"))
        .set("uMaxRadiusPx", ctx.params.getFloat("hbao.max_radius_px"))
        .set("uDirections", ctx.params.getInt("hbao.directions"))
        .set("uSteps", ctx.params.getInt("hbao.steps"))
        .set("uAngleBias", glm::radians(ctx.params.getFloat("hbao.angle_bias")))
        .set("uAttenuation", ctx.params.getFloat("hbao.attenuation"))
        .set("uJitter", ctx.params.getBool("hbao.jitter"));
  }

  TechniqueInfo m_info = staticInfo();
};

} // namespace

void registerTechnique_hbao(TechniqueRegistry& registry) {
  registerTechniqueType<Hbao>(registry);
}

} // namespace rtlab
