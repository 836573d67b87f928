// SSAO — Mittring 2007, "Finding next gen: CryEngine 2" (SIGGRAPH course), in the normal-oriented
// hemisphere form. Approximates the ao stage's (1/pi) * integral of V_R cos over the hemisphere
// by testing points of a kernel within ao.radius against the depth buffer: by default a
// cosine-distributed hemisphere kernel (its unoccluded fraction estimates the cosine-weighted
// integral); the classic sphere-volume kernel is kept as an option to show its model bias.
#include "frame/frame_graph.h"
#include "frame/registry.h"
#include "params/param_set.h"
#include "techniques/common/ao/ao_pass.h"

namespace rtlab {
namespace {

class Ssao final : public AoTechnique {
public:
  Ssao() : AoTechnique(staticInfo()) {}

  static TechniqueInfo staticInfo() {
    TechniqueInfo info;
    info.id = "ssao";
    info.stage = "ao";
    info.title = "Screen-space ambient occlusion (Mittring 2007)";
    info.summary = "Fraction of kernel points within ao.radius that lie in front of the depth buffer";
    info.showcaseScene = "cornell";
    info.params = {
        ParamSpec::integer("ssao.samples", "Samples", 16, 1, 64)
            .logScale()
            .withUnit("points")
            .withHelp("Kernel points tested per pixel"),
        ParamSpec::choice("ssao.kernel", "Kernel", {"cosine", "sphere"}, 0)
            .withFlags(kParamRecompile)
            .withHelp("cosine: hemisphere about the normal, cosine-distributed (estimates the cosine-weighted AO); "
                      "sphere: the classic sphere volume, visibility 2(1 - occluded fraction)"),
        ParamSpec::choice("ssao.distribution", "Length distribution", {"uniform", "center", "shell"}, 2)
            .withFlags(kParamRecompile)
            .withHelp("Point distances along each direction: uniform in the volume, concentrated near the "
                      "centre (mix(0.1, 1, s^2)), or all at ao.radius (shell: behind a height field exactly when "
                      "the ray hits within the radius)"),
        ParamSpec::boolean("ssao.rotate", "Per-pixel rotation", true)
            .withHelp("Turn the kernel about the normal and offset its lengths per pixel by blue noise"),
        ParamSpec::choice("ssao.range_check", "Range check", {"off", "smooth", "distance"}, 1)
            .withHelp("Discount occluders far from the point: off; smooth, smoothstep(0, 1, R/|dz|) (Crytek); "
                      "distance, only a stored surface within ao.radius occludes"),
        ParamSpec::real("ssao.bias", "Depth bias", 0.025, 0.0, 0.1)
            .withUnit("scene units")
            .withHelp("A point is occluded only when the stored surface is nearer than it by more than this"),
        ParamSpec::real("ssao.power", "Power", 1.0, 0.5, 4.0)
            .withHelp("Contrast: the result is raised to this power (1 keeps the estimate unbiased)"),
    };
    return withAoChain(std::move(info));
  }

private:
  AoEstimatorPass estimator(const ParamSet& params) const override {
    AoEstimatorPass pass;
    pass.fragment = "ssao/ssao.frag";
    if (params.getEnumName("ssao.kernel") == "sphere") pass.defines.push_back("KERNEL_SPHERE");
    const std::string& lengths = params.getEnumName("ssao.distribution");
    if (lengths == "center") pass.defines.push_back("LENGTH_CENTER");
    if (lengths == "shell") pass.defines.push_back("LENGTH_SHELL");
    pass.bind = [](PassContext& ctx, gl::Program& p) {
      p.set("uSampleCount", ctx.params.getInt("ssao.samples"))
          .set("uBias", ctx.params.getFloat("ssao.bias"))
          .set("uPower", ctx.params.getFloat("ssao.power"))
          .set("uRangeCheck", ctx.params.getEnum("ssao.range_check"))
          .set("uRotate", ctx.params.getBool("ssao.rotate"));
    };
    return pass;
  }
};

} // namespace

void registerTechnique_ssao(TechniqueRegistry& registry) {
  registerTechniqueType<Ssao>(registry);
}

} // namespace rtlab
