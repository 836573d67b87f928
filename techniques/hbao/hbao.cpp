// HBAO — Bavoil, Sainz & Dimitrov 2008, "Image-space horizon-based ambient occlusion"
// (SIGGRAPH 2008 talk; ShaderX7, chapter 6.2). Approximates the ao stage's output, the
// cosine-weighted unoccluded fraction within ao.radius, from the depth buffer alone: around each
// pixel it marches a few screen-space directions, finds in each the highest horizon among the
// surface points within ao.radius, and integrates the open part of the hemisphere above those
// horizons. The default integral weights directions by the cosine (the reference's quantity);
// Bavoil's solid-angle integral with per-sample distance attenuation is an option, to show its
// model bias. Blur, half resolution and debug views come from the shared ao chain (ao_pass.h).
#include "frame/frame_graph.h"
#include "frame/registry.h"
#include "params/param_set.h"
#include "techniques/common/ao/ao_pass.h"

#include <glm/glm.hpp>

#include <cmath>

namespace rtlab {
namespace {

class Hbao final : public AoTechnique {
public:
  Hbao() : AoTechnique(staticInfo()) {}

  static TechniqueInfo staticInfo() {
    TechniqueInfo info;
    info.id = "hbao";
    info.stage = "ao";
    info.title = "Horizon-based ambient occlusion (Bavoil, Sainz & Dimitrov 2008)";
    info.summary = "Horizons marched along screen-space directions bound the open part of the hemisphere within "
                   "ao.radius";
    info.showcaseScene = "cornell";
    info.params = {
        ParamSpec::integer("hbao.directions", "Directions", 8, 1, 32)
            .logScale()
            .withUnit("directions")
            .withHelp("Screen-space directions marched per pixel, evenly spaced (rotated per pixel with hbao.jitter)"),
        ParamSpec::integer("hbao.steps", "Steps", 6, 1, 32)
            .logScale()
            .withUnit("taps")
            .withHelp("Depth taps per direction, from the nearest neighbour out to ao.radius projected into pixels"),
        ParamSpec::real("hbao.max_radius_px", "Max pixel radius", 128.0, 4.0, 1024.0)
            .logScale()
            .withUnit("pixels")
            .withHelp("Cap on ao.radius projected into frame pixels (near the camera it bounds cost and reach)"),
        ParamSpec::real("hbao.angle_bias", "Angle bias", 10.0, 0.0, 60.0)
            .withUnit("degrees")
            .withHelp("A tap occludes only if it rises this far above the tangent plane (hides tessellation)"),
        ParamSpec::real("hbao.attenuation", "Distance attenuation", 0.0, 0.0, 1.0)
            .withHelp("Occluder weight 1 - a r^2/R^2 at distance r: 0 keeps the hard ao.radius cut of the reference, "
                      "1 is Bavoil's falloff"),
        ParamSpec::boolean("hbao.jitter", "Per-pixel jitter", true)
            .withHelp("Rotate the directions and offset the taps per pixel by blue noise (noise, which the blur "
                      "removes, instead of banding)"),
        ParamSpec::choice("hbao.integral", "Integral", {"cosine", "solid_angle"}, 0)
            .withFlags(kParamRecompile)
            .withHelp("cosine: cosine-weighted horizon integral (the reference's ao); solid_angle: Bavoil's "
                      "1 - mean (sin h - sin t), with hbao.attenuation=1 the paper's form"),
    };
    return withAoChain(std::move(info));
  }

private:
  AoEstimatorPass estimator(const ParamSet& params) const override {
    AoEstimatorPass pass;
    pass.fragment = "hbao/hbao.frag";
    pass.defines = {params.getEnumName("hbao.integral") == "cosine" ? "HBAO_INTEGRAL 1" : "HBAO_INTEGRAL 0",
                    params.getFloat("hbao.attenuation") > 0.0f ? "HBAO_WEIGHTED 1" : "HBAO_WEIGHTED 0"};
    pass.bind = [](PassContext& ctx, gl::Program& p) {
      const float bias = glm::radians(ctx.params.getFloat("hbao.angle_bias"));
      p.set("uDirections", ctx.params.getInt("hbao.directions"))
          .set("uSteps", ctx.params.getInt("hbao.steps"))
          .set("uMaxRadiusPx", ctx.params.getFloat("hbao.max_radius_px"))
          .set("uAngleBias", bias)
          .set("uBiasCosSin", glm::vec2(std::cos(bias), std::sin(bias)))
          .set("uAttenuation", ctx.params.getFloat("hbao.attenuation"))
          .set("uJitter", ctx.params.getBool("hbao.jitter"));
    };
    return pass;
  }
};

} // namespace

void registerTechnique_hbao(TechniqueRegistry& registry) {
  registerTechniqueType<Hbao>(registry);
}

} // namespace rtlab
